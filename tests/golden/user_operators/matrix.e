class MATRIX
create make
feature
	make (n: INTEGER) do create cells.make_filled (0, 1, n * n); size := n end
	size: INTEGER
	cells: ARRAY [INTEGER]
	item alias "[]" (i, j: INTEGER): INTEGER assign put do Result := cells [(i - 1) * size + j] end
	put (v, i, j: INTEGER) do cells [(i - 1) * size + j] := v end
end
