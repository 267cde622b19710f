class
	SHELF [H -> PRINTABLE rename image as label end]

feature -- Access

	text (a_tag: H): STRING
			-- The old name is gone.
		do
			Result := a_tag.image -- E: VEEN
		end

end
