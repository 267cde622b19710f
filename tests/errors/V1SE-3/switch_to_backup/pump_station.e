note
	description: "Starts a pump, falling back on a backup when it is faulty."

class
	PUMP_STATION

create
	make

feature {NONE} -- Initialization

	make
			-- Create both pumps and start one.
		do
			create primary.make (1)
			create backup.make (2)
			separate primary as p do
				if p.is_faulty then
					p := backup -- E: V1SE(3)
				end
				p.start
			end
		end

feature -- Access

	primary, backup: separate PUMP
			-- The pumps.

end
