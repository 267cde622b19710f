note
	description: "Marks the origin of a map on a separate map server."

class
	MAPPER

create
	make

feature {NONE} -- Initialization

	make
			-- Set the origin and send it to the map server.
		do
			create server.make
			origin.set (1.5, 2.5)
			separate origin as o do -- E: V1SE
				print (o.x)
			end
			separate server as s do
				s.mark (origin.x, origin.y)
			end
		end

feature -- Access

	origin: POSITION
			-- Origin of the map.

	server: separate MAP_SERVER
			-- Keeps the map.

end
