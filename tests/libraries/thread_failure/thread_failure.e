class THREAD_FAILURE
create make
feature
	make
		local
			t: BAD
		do
			create t.make_bad
			t.launch
			t.join
			print ("after join%N")
		end
end
