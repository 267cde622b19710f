-- SYNTAX TEST "source.eiffel" "manifest constants as the samples and the library write them"
class
	LITERALS

feature

	Speed: REAL_64 = 0.1
--                ^^^ constant.numeric.float.eiffel
	Max_unicode_value: NATURAL_32 = 0x10FFFF
--                               ^^^^^^^^ constant.numeric.integer.hexadecimal.eiffel
	Million: INTEGER = 1_000_000
--                  ^^^^^^^^^ constant.numeric.integer.decimal.eiffel
	Small: REAL_64 = 1.5e-3
--                ^^^^^^ constant.numeric.float.eiffel
	Mask: NATURAL_8 = 0b1010_0101
--                 ^^^^^^^^^^^ constant.numeric.integer.binary.eiffel
	Newline: CHARACTER = '%N'
--                    ^^^^ constant.character.eiffel
--                     ^^ constant.character.eiffel constant.character.escape.eiffel
	Letter_a: CHARACTER = '%/97/'
--                     ^^^^^^^ constant.character.eiffel
--                      ^^^^^ constant.character.escape.code.eiffel
	Quote: STRING = "say %"hi%" -- not a comment"
--               ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^ string.quoted.double.eiffel - comment.line.double-dash.eiffel
--                    ^^ constant.character.escape.eiffel
	Usage: STRING = "[
--               ^^ string.quoted.other.verbatim.aligned.eiffel
		Usage: robot [--fast]
--^^^^^^^^^^^^^^^^^^^^^ string.quoted.other.verbatim.aligned.eiffel - comment.line.double-dash.eiffel
		-- inside a verbatim string
--^^^^^^^^^ string.quoted.other.verbatim.aligned.eiffel - comment.line.double-dash.eiffel
	]"
-- <--- string.quoted.other.verbatim.aligned.eiffel

	after_string: BOOLEAN = True
-- <~------------ variable.other.eiffel - string.quoted.other.verbatim.aligned.eiffel
--                       ^^^^ constant.language.eiffel

	Long: STRING = "first part %
--                          ^ string.quoted.double.eiffel constant.character.escape.line-continuation.eiffel
		%second part"
--^ string.quoted.double.eiffel constant.character.escape.line-continuation.eiffel
-- ^^^^^^^^^^^ string.quoted.double.eiffel

	after_long: BOOLEAN = False
-- <~---------- variable.other.eiffel - string.quoted.double.eiffel

	Unfinished: STRING = "no closing quote
--                    ^^^^^^^^^^^^^^^^^ string.quoted.double.eiffel
	after_unfinished: BOOLEAN = False
-- <~---------------- variable.other.eiffel - string.quoted.double.eiffel

	span: INTEGER_INTERVAL
		do
			Result := 1 |..| 10
--             ^^^^ keyword.operator.interval.eiffel
-- ^^^^^^ variable.language.eiffel
			if Result.count \\ 2 = 0 and then attached Current as c then
--                 ^^ keyword.operator.arithmetic.eiffel
--                          ^^^ keyword.operator.logical.eiffel
--                                   ^^^^^^^^ storage.modifier.eiffel
--                                            ^^^^^^^ variable.language.eiffel
			end
		end

end
