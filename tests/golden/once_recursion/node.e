class
	NODE

create
	make

feature {NONE} -- Initialization

	make (a_value: INTEGER)
		do
			value := a_value
		end

feature -- Access

	value: INTEGER

	total: INTEGER
			-- `value' plus what a recursive call sees (`value' itself), per object.
		once ("OBJECT")
			Result := value
			Result := Result + total
		end

end
