note
	description: "Constant attributes of every basic type, and attributes with `attribute' bodies and assigners."

class
	CONSTANTS_ATTRIBUTES

create
	make

feature {NONE} -- Initialization

	make
			-- Print constants and lazily initialized attributes.
		do
			print (Max_size.out + " " + Pi.out + " " + Greeting + " " + Letter.out + "%N")
			print (Enabled.out + " " + Big.out + " " + Mask.out + " " + Offset.out + " " + Ratio.out + "%N")
			print (label + "%N")
			label := "changed"
			print (label + "%N")
			print (history.count.out + "%N")
			threshold := 10
			print (threshold.out + "%N")
			if attached limit as l_limit then
				print (l_limit.out + "%N")
			end
			print (Banner + "%N")
		end

feature -- Constants

	Max_size: INTEGER = 100
			-- Largest size.

	Pi: REAL_64 = 3.141_592_653_589_793
			-- Ratio of a circle's circumference to its diameter.

	Greeting: STRING = "Hello"
			-- A friendly word.

	Letter: CHARACTER = 'x'
			-- A letter.

	Enabled: BOOLEAN = True
			-- Is it on?

	Big: INTEGER_64 = 9_000_000_000
			-- More than 32 bits.

	Mask: NATURAL_32 = 0xFF00
			-- A bit mask.

	Offset: INTEGER = -1
			-- A negative constant.

	Ratio: REAL_32 = 0.75
			-- A single-precision constant.

	Banner: STRING_32 = "Ünïcödé ✓"
			-- A constant with characters beyond ASCII.

	Typed: INTEGER_8 = {INTEGER_8} 12
			-- A typed manifest constant as a constant's value.

feature -- Attributes

	label: STRING assign set_label
			-- A label, "unnamed" until set.
		attribute
			Result := "unnamed"
		end

	history: ARRAYED_LIST [STRING]
			-- Past labels, created on first use.
		note
			option: stable
		attribute
			create Result.make (4)
		ensure
			empty_at_start: Result.is_empty
		end

	threshold: INTEGER assign set_threshold
			-- A plain attribute with an assigner.

	limit: detachable STRING
			-- An attribute that may be void.
		attribute
		end

feature -- Element change

	set_label (a_label: STRING)
			-- Set `label'.
		do
			label := a_label
		ensure
			label_set: label = a_label
		end

	set_threshold (n: INTEGER)
			-- Set `threshold'.
		do
			threshold := n
		end

end
