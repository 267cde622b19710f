note
	description: "Character literals, including every special character written with %%."

class
	LITERALS_CHARACTER

create
	make

feature {NONE} -- Initialization

	make
			-- Print the code of each special character.
		local
			c: CHARACTER
			w: CHARACTER_32
		do
			c := 'a'
			show (c)
			c := 'Z'
			show (c)
			c := ' '
			show (c)
			c := '"'
			show (c)
			c := '%''
			show (c)
			c := '%%'
			show (c)
			c := '%"'
			show (c)
			c := '%N'
			show (c)
			c := '%T'
			show (c)
			c := '%R'
			show (c)
			c := '%U'
			show (c)
			c := '%A'
			show (c)
			c := '%B'
			show (c)
			c := '%C'
			show (c)
			c := '%D'
			show (c)
			c := '%F'
			show (c)
			c := '%H'
			show (c)
			c := '%L'
			show (c)
			c := '%Q'
			show (c)
			c := '%S'
			show (c)
			c := '%V'
			show (c)
			c := '%('
			show (c)
			c := '%)'
			show (c)
			c := '%<'
			show (c)
			c := '%>'
			show (c)
			c := '%/65/'
			show (c)
			c := '%/10/'
			show (c)
			w := {CHARACTER_32} 'x'
			print (w.code.out + "%N")
			if c.is_digit or else c >= '0' and c <= '9' then
				print ("digit%N")
			end
		end

feature -- Output

	show (c: CHARACTER)
			-- Print the code of `c'.
		do
			print (c.code.out + "%N")
		end

end
