note
	description: "The symbolic iteration forms of EiffelStudio 19 and later, and `TUPLE []`."

class
	SYMBOLIC_LOOPS

create
	make

feature {NONE} -- Initialization

	make
			-- Check and print some numbers with the symbolic forms.
		local
			numbers: ARRAY [INTEGER]
		do
			numbers := <<3, 5, 8>>
			if ∀ n: numbers ¦ n > 0 and n < 10 then
				print ("all small and positive%N")
			end
			if (∃ n: numbers ¦ n \\ 2 = 0) or numbers.is_empty then
				print ("an even number%N")
			end
			⟳ n: numbers ¦ print (n); print ("%N") ⟲
			on_done := agent report
		end

feature -- Access

	on_done: detachable PROCEDURE [TUPLE []]
			-- Called when done.

	report
			-- Say that all is done.
		do
			print ("done%N")
		ensure
			nothing_changed: ∀ n: <<1, 2>> ¦ n > 0
		end

end
