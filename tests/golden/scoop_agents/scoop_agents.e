note
	description: "SCOOP: agents on separate targets, queries returning separate objects, separate attributes."

class
	SCOOP_AGENTS

create
	make

feature {NONE} -- Initialization

	make
		local
			g: separate GREETER
			other: separate GREETER
			action: separate PROCEDURE [STRING]
		do
			create g
			action := greeting_agent (g)
			run_agent (action, "agent")
			print ("greetings: " + count (g).out + "%N")
			other := spawn (g)
			link (g, other)
			greet_partner (g)
			print ("partner greetings: " + count (other).out + " " + count (g).out + "%N")
		end

feature {NONE} -- Implementation

	greeting_agent (g: separate GREETER): separate PROCEDURE [STRING]
		do
			Result := agent g.greet
		end

	run_agent (a: separate PROCEDURE [STRING]; s: STRING)
		do
			a.call ([s])
		end

	count (g: separate GREETER): INTEGER
		do
			Result := g.greetings
		end

	spawn (g: separate GREETER): separate GREETER
		do
			Result := g.new_greeter
		end

	link (g, p: separate GREETER)
		do
			g.set_partner (p)
		end

	greet_partner (g: separate GREETER)
		do
			if attached g.partner as p then
				separate p as q do
					q.greet ("from the root")
				end
			end
		end

end
