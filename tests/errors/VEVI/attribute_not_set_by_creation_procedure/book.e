class
	BOOK

create
	make

feature {NONE} -- Initialization

	make (a_pages: INTEGER)
			-- Create a book of `a_pages' pages.
		do
			pages := a_pages
		end -- E: VEVI@3

feature -- Access

	title: STRING
			-- Title (never set).

	pages: INTEGER
			-- Number of pages.

end
