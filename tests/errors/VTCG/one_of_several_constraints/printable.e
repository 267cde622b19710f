deferred class
	PRINTABLE

feature -- Access

	image: STRING
			-- Printed form.
		deferred
		end

	merged alias "+" (other: like Current): STRING
			-- Both images.
		do
			Result := image + other.image
		end

end
