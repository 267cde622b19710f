note
	description: "Where a reading comes from, copied on assignment; the name stays where it is."

expanded class
	ORIGIN_TAG

feature -- Access

	source: detachable separate STRING
			-- Name of the station, on whatever processor holds it.

feature -- Element change

	set_source (a_source: separate STRING)
			-- Set `source' to `a_source'.
		do
			source := a_source
		end

end
