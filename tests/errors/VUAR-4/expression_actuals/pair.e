expanded class
	PAIR

feature -- Access

	name: detachable STRING
			-- A reference into the client's processor.

feature -- Element change

	set (s: STRING)
			-- Set `name' to `s'.
		do
			name := s
		end

end
