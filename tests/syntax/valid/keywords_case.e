NOTE
	Description: "Keywords and names are case-insensitive: this class shouts and mumbles."

CLASS
	KEYWORDS_CASE

Create
	MAKE

FEATURE {none} -- Initialization

	Make
			-- Mixed-case keywords everywhere.
		LOCAL
			Count: Integer
			FLAG: boolean
		DO
			COUNT := 3
			Flag := TRUE
			IF count > 2 AND Flag THEN
				Print ("big%N")
			ELSEIF Count = 2 Then
				print ("two%N")
			Else
				PRINT ("small%N")
			END
			FROM
				count := 0
			UNTIL
				COUNT >= 3
			LOOP
				count := Count + 1
			End
			flag := flag AND THEN not FALSE OR ELSE Void = Current
			print (flag.OUT + "%N")
			print (Twice (count).out + "%N")
			PRINT (CURRENT.generating_type.name)
			print ("%N")
		end

feature -- Computation

	twice (N: INTEGER): INTEGER
			-- `n' doubled; `Result' may be written RESULT.
		do
			RESULT := n * 2
		ENSURE
			Doubled: result = N + n
		END

invariant
	always: TRUE

END
