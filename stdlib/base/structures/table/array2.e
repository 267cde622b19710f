note
	description: "[
		Two-dimensional arrays: `height' rows and `width' columns, both numbered from 1;
		`a [row, column]' reads an item and `a [row, column] := v' changes it.
		Traversal (`across', `linear_representation') goes row by row.
	]"

class
	ARRAY2 [G]

inherit
	FINITE [G]
		redefine
			copy,
			is_equal
		end

	ITERABLE [G]
		redefine
			copy,
			is_equal
		end

create
	make,
	make_filled

feature {NONE} -- Initialization

	make (nb_rows, nb_columns: INTEGER_32)
			-- Make an array of `nb_rows' rows and `nb_columns' columns holding default values.
		require
			non_negative_rows: nb_rows >= 0
			non_negative_columns: nb_columns >= 0
		do
			height := nb_rows
			width := nb_columns
			create area.make_empty (nb_rows * nb_columns)
			area.fill_with_default (0, nb_rows * nb_columns - 1)
		ensure
			height_set: height = nb_rows
			width_set: width = nb_columns
		end

	make_filled (a_default_value: G; nb_rows, nb_columns: INTEGER_32)
			-- Make an array of `nb_rows' rows and `nb_columns' columns, every item `a_default_value'.
		require
			non_negative_rows: nb_rows >= 0
			non_negative_columns: nb_columns >= 0
		do
			height := nb_rows
			width := nb_columns
			create area.make_filled (a_default_value, nb_rows * nb_columns)
		ensure
			height_set: height = nb_rows
			width_set: width = nb_columns
		end

feature -- Access

	item alias "[]" (row, column: INTEGER_32): G assign put
			-- Item at `row' and `column'.
		require
			valid_row: 1 <= row and row <= height
			valid_column: 1 <= column and column <= width
		do
			Result := area.item ((row - 1) * width + column - 1)
		end

	has (v: G): BOOLEAN
			-- <Precursor>
		local
			i: INTEGER_32
		do
			from
			until
				Result or i >= area.count
			loop
				if object_comparison then
					Result := area.item (i) ~ v
				else
					Result := area.item (i) = v
				end
				i := i + 1
			end
		end

	new_cursor: ITERATION_CURSOR [G]
			-- <Precursor>
		do
			Result := area.new_cursor
		end

	area: SPECIAL [G]
			-- The items, row by row.

feature -- Measurement

	height: INTEGER_32
			-- Number of rows.

	width: INTEGER_32
			-- Number of columns.

	count: INTEGER_32
			-- Number of items.
		do
			Result := height * width
		end

feature -- Comparison

	is_equal (other: like Current): BOOLEAN
			-- Do the current array and `other' have the same shape and the same items?
		do
			Result := height = other.height and width = other.width and then area.same_items (other.area, 0, 0, count)
		end

feature -- Element change

	put (v: G; row, column: INTEGER_32)
			-- Put `v' at `row' and `column'.
		require
			valid_row: 1 <= row and row <= height
			valid_column: 1 <= column and column <= width
		do
			area.put (v, (row - 1) * width + column - 1)
		ensure
			inserted: item (row, column) = v
		end

	initialize (v: G)
			-- Put `v' everywhere.
		do
			area.fill_with (v, 0, count - 1)
		end

feature -- Resizing

	resize (nb_rows, nb_columns: INTEGER_32)
			-- Grow to `nb_rows' rows and `nb_columns' columns, keeping every item at its
			-- row and column; new items get the default value of G.
		require
			enough_rows: nb_rows >= height
			enough_columns: nb_columns >= width
		local
			new_area: SPECIAL [G]
			row: INTEGER_32
		do
			create new_area.make_empty (nb_rows * nb_columns)
			from
				row := 0
			until
				row >= height
			loop
				new_area.copy_data (area, row * width, row * nb_columns, width)
				new_area.fill_with_default (row * nb_columns + width, (row + 1) * nb_columns - 1)
				row := row + 1
			end
			new_area.fill_with_default (height * nb_columns, nb_rows * nb_columns - 1)
			area := new_area
			height := nb_rows
			width := nb_columns
		ensure
			height_set: height = nb_rows
			width_set: width = nb_columns
		end

feature -- Conversion

	linear_representation: ARRAYED_LIST [G]
			-- The items, row by row.
		local
			i: INTEGER_32
		do
			from
				create Result.make (count)
			until
				i >= area.count
			loop
				Result.extend (area.item (i))
				i := i + 1
			end
		end

feature -- Duplication

	copy (other: like Current)
			-- Take the shape and items of `other', in storage of its own.
		do
			if other /= Current then
				standard_copy (other)
				area := other.area.twin
			end
		end

invariant
	consistent_count: area.count = height * width

end
