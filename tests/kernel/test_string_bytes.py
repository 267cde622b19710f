"""A program's STRING_8 holds bytes, as in EiffelStudio: what it prints, writes to a file or
reads from its arguments is those bytes, one for one, whether or not they are UTF-8."""

from __future__ import annotations

import io

import pytest

import scoopc
from scoopc.exits import Exit

PROGRAM = """class
	BYTES

create
	make

feature

	make
		local
			s: STRING
			args: ARGUMENTS_32
			f: PLAIN_TEXT_FILE
		do
			create args
			create s.make_empty
			s.append_character ('%/233/')
			s.append ("é∀")
			print (s)
			io.put_string (s)
			io.error.put_string (s)
			print (s.count.out + "%N")
			print (argument (1).count.out + " " + args.argument (1).count.out + "%N")
			create f.make_create_read_write ("bytes.txt")
			f.put_string (s)
			f.put_new_line
			f.put_string (argument (1))
			f.close
			create f.make_open_read ("bytes.txt")
			f.read_line
			print (f.last_string.count.out + " " + f.last_string.same_string (s).out + "%N")
			f.close
		end

	argument (i: INTEGER): STRING
		local
			args: ARGUMENTS
		do
			create args
			Result := args.argument (i)
		end

end
"""


@pytest.mark.slow  # compiles and runs a program
def test_printing_and_files_give_the_bytes_back(tmp_path, monkeypatch):
    (tmp_path / "bytes.e").write_text(PROGRAM, encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    out = io.TextIOWrapper(io.BytesIO(), encoding="utf-8")
    err = io.TextIOWrapper(io.BytesIO(), encoding="utf-8", errors="backslashreplace")
    result = scoopc.run([tmp_path / "bytes.e"], ["é"], stdout=out, stderr=err)
    out.flush()
    err.flush()
    assert result.status == Exit.OK, err.buffer.getvalue()
    mine = b"\xe9\xc3\xa9\xe2\x88\x80"  # the byte 233, then the UTF-8 of "é∀"
    assert out.buffer.getvalue() == mine + mine + b"6\n2 1\n6 True\n"
    assert err.buffer.getvalue() == mine
    assert (tmp_path / "bytes.txt").read_bytes() == mine + b"\n\xc3\xa9"
