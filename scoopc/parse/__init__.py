"""The parser stage: Eiffel source text -> syntax trees (scoopc.syntax) and syntax diagnostics.
`parser` drives lark over scoopc/grammar.lark, `builders` turn reductions into tree nodes,
`syntax_errors` and `syntax_terms` explain a syntax error in Eiffel terms."""
