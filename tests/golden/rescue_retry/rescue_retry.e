note
	description: "rescue and retry: a routine that succeeds at its third attempt; exceptions seen in rescue clauses."

class
	RESCUE_RETRY

inherit
	EXCEPTION_MANAGER_FACTORY

create
	make

feature {NONE} -- Initialization

	make
		do
			fragile
			print ("fragile done after " + attempts.out + " attempts%N")
			safe_call (1)
			safe_call (2)
			safe_call (3)
			safe_call (4)
			safe_call (5)
			print ("recovered: " + recovered.out + "%N")
		end

feature {NONE} -- Implementation

	attempts: INTEGER

	recovered: INTEGER

	fragile
			-- Fails twice, then succeeds.
		do
			attempts := attempts + 1
			print ("attempt " + attempts.out + "%N")
			if attempts < 3 then
				raise_developer ("not yet")
			end
			print ("succeeded%N")
		rescue
			print ("rescue after attempt " + attempts.out + "%N")
			retry
		end

	raise_developer (text: STRING)
		local
			e: DEVELOPER_EXCEPTION
		do
			create e
			e.set_description (text)
			e.raise
		end

	safe_call (kind: INTEGER)
			-- Run `failing (kind)', reporting its exception instead of failing.
		local
			failed: BOOLEAN
		do
			if failed then
				recovered := recovered + 1
			else
				failing (kind)
				print ("no failure%N")
			end
		rescue
			if attached exception_manager.last_exception as e then
				print ("caught " + e.original.generator + " tag: " + e.original.tag + "%N")
			end
			failed := True
			retry
		end

	failing (kind: INTEGER)
		do
			inspect kind
			when 1 then
				raise_developer ("custom failure")
			when 2 then
				positive_only (-1)
			when 3 then
				print (broken_promise)
			when 4 then
				check
					never: kind = 0
				end
			else
				print ("kind " + kind.out + "%N")
			end
		end

	broken_promise: INTEGER
		do
			Result := 1
		ensure
			zero: Result = 0
		end

	positive_only (n: INTEGER)
		require
			positive: n > 0
		do
		end

end
