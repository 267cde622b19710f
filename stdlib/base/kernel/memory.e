note
	description: "[
		Control of the garbage collector. The host's collector does the work: `collect'
		and `full_collect' run a collection; the other settings are accepted and have no effect.
	]"

class
	MEMORY

feature -- Status report

	collecting: BOOLEAN
			-- Is automatic garbage collection on?
		external
			"Python"
		end

feature -- Status setting

	collection_on
			-- Turn automatic garbage collection on.
		external
			"Python"
		end

	collection_off
			-- Turn automatic garbage collection off.
		external
			"Python"
		end

	allocate_fast
			-- Favour speed over memory use (no effect).
		do
		end

	allocate_compact
			-- Favour memory use over speed (no effect).
		do
		end

	allocate_tiny
			-- Use as little memory as possible (no effect).
		do
		end

	execute_without_collection (a_action: PROCEDURE [TUPLE])
			-- Call `a_action' with garbage collection off, then restore it.
		local
			l_collecting: BOOLEAN
		do
			l_collecting := collecting
			collection_off
			a_action.call (Void)
			if l_collecting then
				collection_on
			end
		end

feature -- Removal

	collect
			-- Run a partial collection.
		external
			"Python"
		end

	full_collect
			-- Run a full collection.
		external
			"Python"
		end

	full_coalesce
			-- Compact the free memory (no effect beyond a collection).
		external
			"Python"
		end

	free (object: ANY)
			-- Hint that `object' is no longer used (no effect).
		do
		end

	dispose
			-- Action before the object is reclaimed (none).
		do
		end

end
