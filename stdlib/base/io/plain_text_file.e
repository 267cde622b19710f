note
	description: "Files of text, read and written as characters and lines."

class
	PLAIN_TEXT_FILE

inherit
	FILE

create
	make,
	make_with_name,
	make_with_path,
	make_open_read,
	make_open_write,
	make_open_append,
	make_open_read_write,
	make_create_read_write,
	make_open_read_append

end
