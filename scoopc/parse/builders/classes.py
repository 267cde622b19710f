"""Parser stage, classes: reductions of class headers, notes, generics, inheritance, creation
clauses, converters and feature clauses.

Input: the children of one rule. Output: ClassDeclaration and its parts.
"""

from __future__ import annotations

import dataclasses
from typing import Any

from ... import syntax as s
from .base import BuilderBase, Keyworded


class ClassBuilder(BuilderBase):
    def start(self, c: list) -> list:
        return c

    def class_declaration(self, c: list) -> s.ClassDeclaration:
        i = 1
        while c[i].type != "CLASS":
            i += 1
        marks = tuple(mark.value.lower() for mark in c[1:i])
        name, generics, obsolete, inherits, creators, converters = c[i + 1 : i + 7]
        clauses, invariant, trailing = list(c[i + 7 : -3]), c[-3], c[-2]
        if trailing is None and clauses:
            trailing = self._trailing_notes(clauses)
        notes = tuple(c[0] or ()) + tuple(trailing or ())
        start = c[0].keyword if c[0] is not None else c[1]
        return s.ClassDeclaration(
            self.ident(name),
            marks,
            generics or (),
            obsolete.value if obsolete else None,
            inherits,
            creators,
            converters or (),
            tuple(clauses),
            invariant or (),
            notes,
            self.span(start, c[-1]),
        )

    def _trailing_notes(self, clauses: list) -> tuple | None:
        """A `note` clause at the end of a class whose last feature is an attribute is first
        read as that attribute's note (the grammar shifts); give it back to the class."""
        last = clauses[-1]
        feature = last.features[-1] if last.features else None
        if (
            not isinstance(feature, (s.Attribute, s.Constant))
            or not feature.notes
            or getattr(feature, "body", None) is not None
        ):
            return None
        end = feature.value if isinstance(feature, s.Constant) else feature.type
        kept = dataclasses.replace(feature, notes=(), span=self.span(feature.names[0], end))
        clauses[-1] = dataclasses.replace(last, features=last.features[:-1] + (kept,), span=self.span(last, kept))
        return feature.notes

    def header_mark(self, c: list) -> Any:
        return c[0]

    def obsolete(self, c: list) -> s.ManifestString:
        return self.manifest_string(c)

    def inheritance(self, c: list) -> tuple:
        return tuple(c)

    def creators(self, c: list) -> tuple:
        return tuple(c)

    # ---- notes -----------------------------------------------------------------------
    def note_clause(self, c: list) -> Keyworded:
        if c[0].type == "INDEXING":
            self.obsolete_form(c[0], "`indexing` is the obsolete spelling of `note`", "write `note` instead")
        return Keyworded.of(c[0], (entry for entry in c[1:] if entry is not None))

    def note_entry(self, c: list) -> s.Note:
        values = tuple(c[1:])
        return s.Note(self.ident(c[0]), values, self.span(c[0], values[-1]))

    def note_word(self, c: list) -> s.Identifier:
        return self.ident(c[0])

    # ---- formal generics -------------------------------------------------------------
    def formal_generics(self, c: list) -> tuple:
        return tuple(c[1:-1])

    def formal_generic(self, c: list) -> s.FormalGeneric:
        mark, name, constraints, creators = c
        last = creators[-1] if creators else (constraints[-1] if constraints else name)
        return s.FormalGeneric(
            self.ident(name),
            mark.value.lower() if mark else None,
            constraints or (),
            creators,
            self.span(mark or name, last),
        )

    def generic_mark(self, c: list) -> Any:
        return c[0]

    def single_constraint(self, c: list) -> tuple:
        return (c[0],)

    def multiple_constraint(self, c: list) -> tuple:
        return tuple(c)

    def constraining_type(self, c: list) -> s.Constraint:
        renames = tuple(r for r in c[2:] if r is not None)
        return s.Constraint(c[0], renames, self.span(c[0], renames[-1] if renames else c[0]))

    # ---- inheritance -----------------------------------------------------------------
    def inherit_clause(self, c: list) -> s.InheritClause:
        keyword, non_conformance = c[0], c[1]
        parents = tuple(p for p in c[2:] if p is not None)
        last = parents[-1] if parents else (non_conformance or keyword)
        return s.InheritClause(non_conformance is None, parents, self.span(keyword, last))

    def non_conformance(self, c: list) -> s.Identifier:
        return self.ident(c[0])

    def parent(self, c: list) -> s.Parent:
        type_, adaptation = c
        if adaptation is None:
            return s.Parent(type_, (), (), (), (), (), type_.span)
        parts, end = adaptation
        return s.Parent(
            type_,
            parts.get("rename", ()),
            parts.get("export", ()),
            parts.get("undefine", ()),
            parts.get("redefine", ()),
            parts.get("select", ()),
            self.span(type_, end),
        )

    def feature_adaptation(self, c: list) -> tuple:
        parts: dict[str, tuple] = {}
        for part in c[:-1]:
            kind = part.keyword.value.lower()
            parts[kind] = parts.get(kind, ()) + tuple(part)
        return parts, c[-1]

    def rename_clause(self, c: list) -> Keyworded:
        return Keyworded.of(c[0], (r for r in c[1:] if r is not None))

    def export_clause(self, c: list) -> Keyworded:
        return Keyworded.of(c[0], (e for e in c[1:] if e is not None))

    def undefine_clause(self, c: list) -> Keyworded:
        return Keyworded.of(c[0], c[1] or ())

    def redefine_clause(self, c: list) -> Keyworded:
        return Keyworded.of(c[0], c[1] or ())

    def select_clause(self, c: list) -> Keyworded:
        return Keyworded.of(c[0], c[1] or ())

    def rename_pair(self, c: list) -> s.Rename:
        old, new = c
        return s.Rename(self.ident(old), new, self.span(old, new))

    def export_item(self, c: list) -> s.ExportItem:
        (clients, opening, closing), features = c
        if isinstance(features, tuple):
            last = features[-1] if features else closing
            return s.ExportItem(clients, features, self.span(opening, last))
        return s.ExportItem(clients, None, self.span(opening, features))

    def export_all(self, c: list) -> Any:
        return c[0]

    def feature_list(self, c: list) -> tuple:
        return tuple(self.ident(name) for name in c)

    def clients(self, c: list) -> tuple:
        names = tuple(self.ident(name) for name in c[1:-1] if name is not None)
        return names, c[0], c[-1]

    # ---- creation clauses, converters, feature clauses -------------------------------
    def creation_clause(self, c: list) -> s.CreationClause:
        keyword, clients, procedures = c
        procedures = procedures or ()
        last = procedures[-1] if procedures else (clients[2] if clients else keyword)
        return s.CreationClause(clients[0] if clients else None, procedures, self.span(keyword, last))

    def converters(self, c: list) -> tuple:
        return tuple(c)

    def creation_converter(self, c: list) -> s.Converter:
        name, _, types, closing = c
        return s.Converter(self.ident(name), types, True, self.span(name, closing))

    def query_converter(self, c: list) -> s.Converter:
        name, types = c
        return s.Converter(self.ident(name), types, False, self.span(name, types[-1]))

    def feature_clause(self, c: list) -> s.FeatureClause:
        keyword, clients = c[0], c[1]
        features = tuple(f for f in c[2:] if f is not None)
        last = features[-1] if features else (clients[2] if clients else keyword)
        return s.FeatureClause(clients[0] if clients else None, features, self.span(keyword, last))
