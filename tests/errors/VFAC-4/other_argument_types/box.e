class
	BOX

feature -- Access

	value: INTEGER assign set_value
			-- Content.

	item (i: INTEGER): INTEGER assign put -- E: VFAC(4)
			-- Content times `i'.
		do
			Result := value * i
		end

	at (i: INTEGER; s: STRING): INTEGER assign put_at
			-- Content plus `i' plus the length of `s'.
		do
			Result := value + i + s.count
		end

feature -- Element change

	set_value (v: INTEGER)
			-- Set `value' to `v'.
		do
			value := v
		end

	put (v: INTEGER; s: STRING)
			-- Set `value' to `v'.
		do
			value := v + s.count
		end

	put_at (v, i: INTEGER; s: STRING)
			-- Set `value' so that `at (i, s)' is `v'.
		do
			value := v - i - s.count
		end

end
