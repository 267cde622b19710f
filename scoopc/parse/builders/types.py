"""Parser stage, types: reductions of class, tuple and anchored types and their marks.

Input: the children of one type rule. Output: ClassType, TupleType or AnchoredType nodes.
"""

from __future__ import annotations

import dataclasses

from ... import syntax as s
from .base import BuilderBase

_ATTACHMENT = {"attached", "detachable"}
_VARIANCE = {"frozen", "variant"}
# The attachment marks before ECMA-367's keywords (EiffelStudio 6.x): `?T` detachable, `!T` attached.
_OLD_MARKS = {"?": "detachable", "!": "attached"}


class TypeBuilder(BuilderBase):
    def type(self, c: list) -> s.Type:
        base = c[-1]
        if len(c) == 1:
            return base
        words = [_OLD_MARKS.get(mark.value, mark.value.lower()) for mark in c[:-1]]
        for mark in c[:-1]:
            if mark.value in _OLD_MARKS:
                self.obsolete_form(
                    mark,
                    f"`{mark.value}T` is the obsolete spelling of `{_OLD_MARKS[mark.value]} T`",
                    f"write `{_OLD_MARKS[mark.value]} T`",
                )
        attachment = next((w for w in words if w in _ATTACHMENT), None)
        variance = next((w for w in words if w in _VARIANCE), None)
        return dataclasses.replace(
            base, attachment=attachment, separate="separate" in words, variance=variance, span=self.span(c[0], base)
        )

    def type_mark(self, c: list):
        return c[0]

    def class_type(self, c: list) -> s.Type:
        name, generics = c
        if generics is None:
            if name.value.lower() == "tuple":
                return s.TupleType((), (), None, False, None, self.tspan(name))
            return s.ClassType(self.ident(name), (), None, False, None, self.tspan(name))
        groups, closing = generics
        span = self.span(name, closing)
        if len(groups) > 1:
            # Groups (each optionally ended by `;`) are only TUPLE's labelled declarations.
            for group_types, label_type in groups:
                if label_type is None:
                    self.report(
                        "SYNTAX",
                        group_types[-1],
                        found="a type without a label",
                        expected="`,` between actual generic parameters",
                    )
                    break
        if name.value.lower() == "tuple":
            return self._tuple_type(groups, span)
        if not groups:
            self.report("SYNTAX", closing, found="`]`", expected="a type (only TUPLE may have empty brackets)")
        types = []
        for group_types, label_type in groups:
            if label_type is not None:
                self.report("SYNTAX", label_type, found="`:`", expected="a type (only TUPLE types have labels)")
            types.extend(group_types)
        return s.ClassType(self.ident(name), tuple(types), None, False, None, span)

    def _tuple_type(self, groups: list, span) -> s.TupleType:
        if all(label_type is None for _, label_type in groups):
            types = tuple(t for group_types, _ in groups for t in group_types)
            return s.TupleType(types, (), None, False, None, span)
        types: list[s.Type] = []
        labels: list[s.Identifier] = []
        for group_types, label_type in groups:
            for label in group_types:
                labels.append(self._label(label))
                types.append(label_type if label_type is not None else label)
        return s.TupleType(tuple(types), tuple(labels), None, False, None, span)

    def _label(self, label: s.Type) -> s.Identifier:
        if isinstance(label, s.ClassType) and not label.generics and label.attachment is None and not label.separate:
            return label.name
        self.report("SYNTAX", label, found="a type", expected="a label name before `:`")
        return s.Identifier("?", "?", label.span)

    def actual_generics(self, c: list) -> tuple:
        return c[1:-1], c[-1]

    def empty_generics(self, c: list) -> tuple:
        """`TUPLE []`, the same as `TUPLE` (EiffelStudio allows empty brackets for TUPLE only)."""
        return (), c[-1]

    def generic_group(self, c: list) -> tuple:
        return tuple(c[:-1]), c[-1]

    def like_current(self, c: list) -> s.AnchoredType:
        anchor = s.Current(self.tspan(c[1]))
        return s.AnchoredType(anchor, None, False, None, self.span(c[0], c[1]))

    def like_feature(self, c: list) -> s.AnchoredType:
        first = c[1]
        anchor: s.Expression = s.UnqualifiedCall(self.ident(first), (), self.tspan(first))
        anchor = self._anchor_path(anchor, c[2:])
        return s.AnchoredType(anchor, None, False, None, self.span(c[0], anchor))

    def like_static(self, c: list) -> s.AnchoredType:
        brace, type_, first = c[1], c[2], c[3]
        anchor: s.Expression = s.StaticCall(type_, self.ident(first), (), self.span(brace, first))
        anchor = self._anchor_path(anchor, c[4:])
        return s.AnchoredType(anchor, None, False, None, self.span(c[0], anchor))

    def _anchor_path(self, anchor: s.Expression, names: list) -> s.Expression:
        for name in names:
            anchor = s.QualifiedCall(anchor, self.ident(name), (), self.span(anchor, name))
        return anchor

    def type_list(self, c: list) -> tuple:
        return tuple(c)
