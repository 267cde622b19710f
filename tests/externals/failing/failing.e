note
	description: "A Python external that raises: an EXTERNAL_FAILURE, which a rescue clause can catch."

class
	FAILING

create
	make

feature

	make
		do
			print (safe_ratio (6, 3).out + "%N")
			print (safe_ratio (1, 0).out + "%N")
			print (ratio (1, 0).out + "%N")
		end

	safe_ratio (a, b: INTEGER): REAL_64
		local
			failed: BOOLEAN
		do
			if failed then
				Result := -1.0
			else
				Result := ratio (a, b)
			end
		rescue
			if attached {EXTERNAL_FAILURE} (create {EXCEPTION_MANAGER}).last_exception as e then
				print ("caught: " + e.code.out + "%N")
			end
			failed := True
			retry
		end

	ratio (a, b: INTEGER): REAL_64 external "Python" alias "failing_mod.ratio" end

end
