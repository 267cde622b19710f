"""The language server (`scoopc lsp`): the checker's diagnostics, hover, definitions, references,
completion, outline, folding and quick fixes for editors, over LSP on stdio (server.py), built on
the driver's Compilation with the editor's unsaved buffers (analysis.py)."""
