-- SYNTAX TEST "source.eiffel" "samples/producer_consumer/consumer.e: classes, separate arguments, wait conditions"
note
-- <---- keyword.other.declaration.eiffel
	description: "Takes items out of a shared buffer, waiting while it is empty."
--            ^ string.quoted.double.eiffel punctuation.definition.string.begin.eiffel
--             ^^^^^^^^^^^ string.quoted.double.eiffel

class
-- <----- storage.type.class.eiffel
	CONSUMER
-- <~-------- entity.name.type.eiffel

feature {NONE} -- Initialization
-- <------- keyword.other.declaration.eiffel
--       ^^^^ entity.name.type.eiffel
--             ^^^^^^^^^^^^^^^^^ comment.line.double-dash.eiffel

	make (a_buffer: separate BOUNDED_BUFFER [INTEGER]; an_id, a_count: INTEGER)
-- <~---- variable.other.eiffel
--               ^^^^^^^^ storage.modifier.separate.scoop.eiffel
--                        ^^^^^^^^^^^^^^ entity.name.type.eiffel
--                                        ^^^^^^^ entity.name.type.eiffel
			-- Consumer `an_id' that will take `a_count' items out of `a_buffer'.
-- ^^ comment.line.double-dash.eiffel punctuation.definition.comment.eiffel
--             ^^^^^^^ comment.line.double-dash.eiffel markup.inline.raw.eiffel
		do
--^^ keyword.control.eiffel
			buffer := a_buffer
--        ^^ keyword.operator.assignment.eiffel
		ensure
--^^^^^^ keyword.control.contract.eiffel
			nothing_taken: taken = 0
--                      ^ keyword.operator.comparison.eiffel
--                        ^ constant.numeric.integer.decimal.eiffel
		end
--^^^ keyword.control.eiffel

	consume (a_buffer: separate BOUNDED_BUFFER [INTEGER])
--                  ^^^^^^^^ storage.modifier.separate.scoop.eiffel
		require
--^^^^^^^ keyword.control.contract.eiffel
			something_there: not a_buffer.is_empty
--                  ^^^ keyword.operator.logical.eiffel
		do
--^^ keyword.control.eiffel
			print ("consumer " + id.out + " took " + taken.out + " items%N")
--        ^^^^^^^^^^^ string.quoted.double.eiffel
--                    ^ keyword.operator.arithmetic.eiffel
--                                                             ^^ string.quoted.double.eiffel constant.character.escape.eiffel
		ensure
			one_more: taken = old taken + 1
--                   ^^^ keyword.control.contract.eiffel
		end

invariant
-- <--------- keyword.control.contract.eiffel
	not_too_many: taken <= count
--                   ^^ keyword.operator.comparison.eiffel

end
-- <--- keyword.control.eiffel
