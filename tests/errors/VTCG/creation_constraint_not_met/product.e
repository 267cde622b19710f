class
	PRODUCT

feature {NONE} -- Initialization

	make
			-- A product.
		do
		end

end
