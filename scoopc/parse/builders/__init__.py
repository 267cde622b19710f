"""Parser stage, AST building: the reduction callbacks lark calls, one method per grammar rule.

Input: the children of each reduced rule (tokens and nodes). Output: scoopc.syntax nodes;
problems found while building (bad escapes, misplaced constructs) go to `problems`.
"""

from __future__ import annotations

from .classes import ClassBuilder
from .expressions import ExpressionBuilder
from .features import FeatureBuilder
from .instructions import InstructionBuilder
from .types import TypeBuilder


class AstBuilder(ClassBuilder, FeatureBuilder, InstructionBuilder, ExpressionBuilder, TypeBuilder):
    """All builders together: the `transformer` handed to lark."""
