note
	description: "Starts probes over a list of sensor queries."

class
	SENSOR_PANEL

create
	make

feature {NONE} -- Initialization

	make
			-- Start probes over two queries.
		local
			l_queries: ARRAYED_LIST [separate FUNCTION [detachable separate ANY]]
			l_plain: ARRAYED_LIST [separate FUNCTION [ANY]]
		do
			create l_queries.make (2)
			l_queries.extend (agent reading)
			l_queries.extend (agent reading)
			create l_plain.make (1)
			l_plain.extend (agent level)
			start (l_queries, l_plain)
		end

feature -- Basic operations

	start (a_queries: LIST [separate FUNCTION [detachable separate ANY]]; a_plain: LIST [separate FUNCTION [ANY]])
			-- Start a probe for each query.
		local
			l_probe: separate PROBE
		do
			across a_queries as q loop
				create l_probe.evaluate (q.item) -- E: VUAR(2)
				create l_probe.evaluate_any (q.item)
			end
			across a_plain as q loop
				create l_probe.evaluate (q.item)
			end
		end

feature -- Access

	reading: detachable separate ANY
			-- Last reading of the sensor.
		do
			Result := "ok"
		end

	level: STRING
			-- Level of the battery.
		do
			Result := "full"
		end

end
