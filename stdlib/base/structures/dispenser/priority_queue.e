note
	description: "Dispensers whose `item' is the largest item (by the order of COMPARABLE)."

deferred class
	PRIORITY_QUEUE [G -> COMPARABLE]

inherit
	DISPENSER [G]

end
