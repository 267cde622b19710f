note
	description: "inspect: single values, lists, ranges, characters, constants; no matching branch is an exception."

class
	INSPECT_BRANCHES

inherit
	EXCEPTION_MANAGER_FACTORY

create
	make

feature {NONE} -- Initialization

	make
		local
			i: INTEGER
		do
			from
				i := -1
			until
				i > 12
			loop
				print (i.out + ": " + number_kind (i) + "%N")
				i := i + 1
			end
			across ("aZ7 ?%N") as c loop
				print (character_kind (c.item) + " ")
			end
			print ("%N")
			print (color_name (Green) + " " + color_name (Blue) + "%N")
			print (unmatched (2) + "%N")
			print (unmatched (5) + "%N")
		end

feature {NONE} -- Implementation

	Red: INTEGER = 1
	Green: INTEGER = 2
	Blue: INTEGER = 3

	number_kind (n: INTEGER): STRING
		do
			inspect n
			when 0 then
				Result := "zero"
			when 1 then
				Result := "one"
			when 2, 3 then
				Result := "two or three"
			when 4 .. 6 then
				Result := "four to six"
			when 7 .. 9, 11 then
				Result := "seven to nine, or eleven"
			else
				Result := "other"
			end
		end

	character_kind (c: CHARACTER): STRING
		do
			inspect c
			when 'a' .. 'z' then
				Result := "lower"
			when 'A' .. 'Z' then
				Result := "upper"
			when '0' .. '9' then
				Result := "digit"
			when ' ', '%N', '%T' then
				Result := "blank"
			else
				Result := "other"
			end
		end

	color_name (c: INTEGER): STRING
		do
			inspect c
			when Red then
				Result := "red"
			when Green then
				Result := "green"
			when Blue then
				Result := "blue"
			end
		end

	unmatched (n: INTEGER): STRING
			-- No `else': a value without a branch raises BAD_INSPECT_VALUE.
		local
			failed: BOOLEAN
		do
			if failed then
				Result := "no branch for " + n.out
			else
				inspect n
				when 1, 2 then
					Result := "branch for " + n.out
				end
			end
		rescue
			if attached exception_manager.last_exception as e then
				print ("rescued " + e.generator + "%N")
			end
			failed := True
			retry
		end

end
