class
	BOX

feature -- Access

	value: INTEGER assign set_value
			-- Content.

	name: STRING assign set_name -- E: VFAC(3)
			-- Name.
		do
			Result := value.out
		end

	label: STRING assign set_label
			-- Label.
		do
			Result := "box " + value.out
		end

feature -- Element change

	set_value (v: INTEGER)
			-- Set `value' to `v'.
		do
			value := v
		end

	set_name (v: INTEGER)
			-- Set `value' to `v'.
		do
			value := v
		end

	set_label (s: detachable STRING)
			-- Set `value' to the length of `s'.
		do
			if attached s then
				value := s.count
			end
		end

end
