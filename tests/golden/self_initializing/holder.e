class
	HOLDER [G]

feature -- Access

	content: G
			-- Self-initializing only when G is a reference type.
		attribute
			print ("(body of content runs) ")
		end

end
