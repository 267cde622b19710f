class
	ANCESTOR

end
