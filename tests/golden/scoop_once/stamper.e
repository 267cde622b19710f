class
	STAMPER

feature -- Access

	stamps: ARRAYED_LIST [INTEGER]
			-- One list per region (processor).
		once
			create Result.make (4)
		end

	region_tag (t: INTEGER): INTEGER
			-- The first `t' given in this region.
		once
			Result := t
		end

	process_tag (t: INTEGER): INTEGER
			-- The first `t' given in the whole program.
		once ("PROCESS")
			Result := t
		end

feature -- Change

	stamp (v: INTEGER)
		do
			stamps.extend (v)
		end

end
