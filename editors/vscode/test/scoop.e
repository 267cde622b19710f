-- SYNTAX TEST "source.eiffel" "SCOOP constructs as samples/dining_philosophers and samples/exploration write them"
class
	TABLE

feature

	eat (left, right: separate FORK)
--                 ^^^^^^^^ storage.modifier.separate.scoop.eiffel
--                          ^^^^ entity.name.type.eiffel
		require
--^^^^^^^ keyword.control.contract.eiffel
			both_free: not left.in_use and not right.in_use
-- ^^^^^^^^^ variable.other.eiffel
		do
			separate left as l, right as r do
-- ^^^^^^^^ storage.modifier.separate.scoop.eiffel
--               ^^ keyword.control.eiffel
--                                ^^ keyword.control.eiffel
				l.pick
			end
			create {separate FORK} fork.make
-- ^^^^^^ keyword.other.declaration.eiffel
--         ^^^^^^^^ storage.modifier.separate.scoop.eiffel
			create <NONE> passive.make
--         ^^^^ entity.name.type.eiffel
			across forks is f loop
-- ^^^^^^ keyword.control.eiffel
--              ^^ keyword.control.eiffel
--                   ^^^^ keyword.control.eiffel
				Precursor {PARENT} (f)
--  ^^^^^^^^^ variable.language.eiffel
			end
		rescue
--^^^^^^ keyword.control.eiffel
			retry
-- ^^^^^ keyword.control.eiffel
		end

	fork: detachable separate FORK
--     ^^^^^^^^^^ storage.modifier.eiffel
--                ^^^^^^^^ storage.modifier.separate.scoop.eiffel

end
