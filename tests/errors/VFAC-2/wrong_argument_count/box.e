class
	BOX

feature -- Access

	value: INTEGER assign set_value
			-- Content.

	size: INTEGER assign set_size -- E: VFAC(2)
			-- Capacity.

	item alias "[]" (i: INTEGER): INTEGER assign put_item -- E: VFAC(2)
			-- Content times `i'.
		do
			Result := value * i
		end

	at (i: INTEGER): INTEGER assign put
			-- Content plus `i'.
		do
			Result := value + i
		end

feature -- Element change

	set_value (v: INTEGER)
			-- Set `value' to `v'.
		do
			value := v
		end

	set_size (v, w: INTEGER)
			-- Set `size' to `v' + `w'.
		do
			size := v + w
		end

	put_item (v: INTEGER)
			-- Set `value' to `v'.
		do
			value := v
		end

	put (v, i: INTEGER)
			-- Set `value' so that `at (i)' is `v'.
		do
			value := v - i
		end

end
