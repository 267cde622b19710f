class
	AGENT_CALL_OMITTED_TUPLE

create
	make

feature

	make
			-- `p.call` means `p.call ([])` (EiffelStudio accepts the omitted empty tuple).
		local
			p: PROCEDURE
			f: FUNCTION [INTEGER]
		do
			p := agent do print ("called%N") end
			p.call
			f := agent: INTEGER do Result := 42 end
			print (f.item.out + "%N")
		end

end
