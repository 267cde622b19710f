class
	TOOL -- E: VSCN

end
