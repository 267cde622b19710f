class
	DATA

end
