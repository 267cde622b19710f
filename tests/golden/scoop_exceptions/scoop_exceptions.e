note
	description: "SCOOP exceptions: a failed asynchronous call is lost (reported on stderr); a failed query raises in the client."

class
	SCOOP_EXCEPTIONS

inherit
	EXCEPTION_MANAGER_FACTORY

create
	make

feature {NONE} -- Initialization

	make
		local
			f: separate FRAGILE
		do
			create f
			fire_and_forget (f)
			print ("after the lost exception%N")
			set (f, 7)
			print ("supplier still usable: " + value (f).out + "%N")
			print (guarded_query (f, 0) + "%N")
			print (guarded_query (f, 5) + "%N")
			print (dirty (f) + "%N")
		end

feature {NONE} -- Implementation

	fire_and_forget (f: separate FRAGILE)
		do
			f.explode
		end

	set (f: separate FRAGILE; v: INTEGER)
		do
			f.set (v)
		end

	value (f: separate FRAGILE): INTEGER
		do
			Result := f.value
		end

	guarded_query (f: separate FRAGILE; v: INTEGER): STRING
		local
			failed: BOOLEAN
		do
			if failed then
				Result := "query failed in the client"
			else
				f.set (v)
				Result := "checked value " + f.checked_value.out
			end
		rescue
			failed := True
			retry
		end

	dirty (f: separate FRAGILE): STRING
			-- A failed command makes the next query of the same reservation fail.
		local
			failed: BOOLEAN
		do
			if failed then
				Result := "dirty region: the query raised"
			else
				f.explode
				Result := "query after failed command returned " + f.value.out
			end
		rescue
			failed := True
			retry
		end

end
