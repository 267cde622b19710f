note
	description: "Plane figures: the deferred root of the shapes hierarchy."
	author: "scoopc test suite"
	keywords: "inheritance", "deferred", "precursor"

deferred class
	SHAPE

inherit
	ANY
		redefine
			out
		end

feature -- Measurement

	area: REAL_64
			-- Surface of the figure.
		deferred
		ensure
			non_negative: Result >= 0.0
		end

	perimeter: REAL_64
			-- Length of the border.
		deferred
		end

	name: STRING
			-- What this figure is called.
		deferred
		end

feature -- Output

	out: STRING
			-- Description with the measurements.
		do
			Result := name + ": area " + area.truncated_to_integer.out + ", perimeter " + perimeter.truncated_to_integer.out
		end

	frozen describe
			-- Print `out'; descendants cannot redefine this.
		do
			print (out + "%N")
		end

invariant
	area_non_negative: area >= 0.0

note
	copyright: "Written for scoopc's tests"
	license: "MIT"
end
