note
	description: "ARGUMENTS (the program's command line after `--') and EXECUTION_ENVIRONMENT."

class
	ARGUMENTS_ENV

inherit
	ARGUMENTS

create
	make

feature {NONE} -- Initialization

	make
		local
			env: EXECUTION_ENVIRONMENT
			i: INTEGER
		do
			print ("argument_count " + argument_count.out + "%N")
			from
				i := 1
			until
				i > argument_count
			loop
				print (i.out + ": [" + argument (i) + "]%N")
				i := i + 1
			end
			print ("word option v at " + index_of_word_option ("v").out + ", x at " + index_of_word_option ("x").out + "%N")
			if attached separate_word_option_value ("name") as n then
				print ("name " + n + "%N")
			end
			print ("number + 1 = " + (argument (4).to_integer + 1).out + "%N")
			print ("argument_array " + argument_array.lower.out + ".." + argument_array.upper.out + "%N")
			create env
			env.put ("golden", "SCOOPC_GOLDEN_VALUE")
			if attached env.item ("SCOOPC_GOLDEN_VALUE") as v then
				print ("environment " + v + "%N")
			end
			print ("unset variable attached: " + (attached env.item ("SCOOPC_GOLDEN_SURELY_UNSET")).out + "%N")
			print ("cpus > 0: " + (env.available_cpu_count > 0).out + "%N")
			env.sleep (2_000_000_000)
			print ("slept%N")
		end

end
