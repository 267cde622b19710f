note
	description: "Root class using expanded, frozen, deferred and obsolete classes."

class
	CLASS_KINDS_APP

create
	make

feature {NONE} -- Initialization

	make
			-- Use each kind of class.
		local
			p, q: POINT
			id: SEALED_ID
			v: VISITOR
			logger: OLD_LOGGER
		do
			create p.make (1, 2)
			q := p
			create q.make (5, 5)
			print (p.out + " " + q.out + " " + p.translated (1, 1).out + "%N")
			create id.make (7)
			print (id.as_text + "%N")
			create {SUM_VISITOR} v
			v.visit_all (<<p, q>>)
			print (v.result_text + "%N")
			create logger
			logger.log ("kinds done")
		end

end
