class
	TOOL

end
