"""The `external "Python"` features of stdlib/base: one module per declaring class, one function
per feature (`current` first), bound by the generated class (docs/CODEGEN.md)."""
