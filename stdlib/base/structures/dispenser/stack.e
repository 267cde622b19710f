note
	description: "Last-in, first-out dispensers: `item' is the newest item, the next one `remove' takes out."

deferred class
	STACK [G]

inherit
	DISPENSER [G]

end
