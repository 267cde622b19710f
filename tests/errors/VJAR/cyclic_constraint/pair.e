class
	PAIR [G -> H, H -> G]

feature -- Access

	first: detachable G

feature -- Change

	put (a_second: H; a_string: STRING)
			-- Mix formals and a class type.
		local
			l_string: detachable STRING
		do
			first := a_second
			l_string := first -- E: VJAR
			first := a_string -- E: VJAR
		end

end
