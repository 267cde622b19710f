note
	description: "The robot's battery: its charge level, drained by driving, refilled at the charging station."

class
	BATTERY_SIGNALER

create
	make

feature {NONE} -- Initialization

	make
			-- Fully charged battery.
		do
			level := Full
		ensure
			full: level = Full
		end

feature -- Access

	level: INTEGER
			-- Charge left, in percent.

	charge_count: INTEGER
			-- Number of times the battery was recharged.

feature -- Element change

	drain (an_amount: INTEGER)
			-- Use `an_amount' percent of charge.
		require
			positive: an_amount > 0
			enough_charge: an_amount <= level
		do
			level := level - an_amount
		ensure
			drained: level = old level - an_amount
		end

	recharge (an_amount: INTEGER)
			-- Add `an_amount' percent of charge, up to full.
		require
			positive: an_amount > 0
		do
			level := (level + an_amount).min (Full)
			if level = Full then
				charge_count := charge_count + 1
			end
		ensure
			charged: level = (old level + an_amount).min (Full)
		end

feature -- Constants

	Full: INTEGER = 100
			-- Level of a full battery.

invariant
	level_in_range: 0 <= level and level <= Full

end
