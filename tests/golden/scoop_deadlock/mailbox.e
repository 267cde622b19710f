class
	MAILBOX

feature -- Access

	has_mail: BOOLEAN

	mail: STRING
		attribute
			Result := ""
		end

feature -- Change

	post (m: separate STRING)
		do
			create mail.make_from_separate (m)
			has_mail := True
		end

end
