note
	description: "First-in, first-out dispensers: `item' is the oldest item, the next one `remove' takes out."

deferred class
	QUEUE [G]

inherit
	DISPENSER [G]

end
