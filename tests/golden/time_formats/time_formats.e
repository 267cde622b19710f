note
	description: "[
		EiffelTime's default output formats for fixed dates and times (never the clock):
		DATE "[0]mm/[0]dd/yyyy", TIME "hh12:[0]mi:[0]ss.ff3 AM", DATE_TIME both with a space;
		arithmetic with DATE_DURATION, TIME_DURATION and DATE_TIME_DURATION.
	]"

class
	TIME_FORMATS

create
	make

feature {NONE} -- Initialization

	make
		local
			d: DATE
			t: TIME
			dt, later: DATE_TIME
			gap: DATE_TIME_DURATION
			durations: ARRAYED_LIST [DURATION]
		do
			create d.make (2024, 1, 5)
			print ("date: " + d.out + "%N")
			create t.make (15, 7, 9)
			print ("afternoon: " + t.out + "%N")
			create t.make (0, 0, 0)
			print ("midnight: " + t.out + "%N")
			create t.make (12, 30, 0)
			print ("noon: " + t.out + "%N")
			create t.make_fine (9, 5, 3.25)
			print ("fine: " + t.out + "%N")
			create dt.make (1999, 12, 31, 23, 59, 59)
			print ("moment: " + dt.out + "%N")
			dt.second_add (1)
			print ("one second later: " + dt.out + "%N")
			create d.make (2024, 2, 28)
			d.day_add (1)
			print ("leap day: " + d.out + ", day of the week: " + d.day_of_the_week.out + "%N")
			d.day_add (1)
			print ("after it: " + d.out + "%N")
			create dt.make (2024, 3, 10, 8, 0, 0)
			create later.make (2024, 3, 12, 20, 30, 15)
			gap := later.relative_duration (dt)
			print ("gap: " + gap.day.out + " days " + gap.hour.out + " h " + gap.minute.out + " min "
				+ gap.second.out + " s%N")
			print ("back: " + (dt + gap).out + "%N")
			print ("ordered: " + (dt < later).out + "%N")
			create durations.make (3)
			durations.extend (create {DATE_DURATION}.make (0, 0, 3))
			durations.extend (create {TIME_DURATION}.make (1, 30, 0))
			durations.extend (gap)
			print ("durations: " + durations.count.out + "%N")
		end

end
