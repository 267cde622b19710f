class
	WATCHER

create
	make

feature

	make (f: separate FLAG)
		do
			flag := f
		end

	live
		do
			print ("watching%N")
			await (flag)
			print ("seen%N")
		end

feature {NONE}

	flag: separate FLAG

	await (f: separate FLAG)
		require
			raised: f.is_set
		do
		end

end
