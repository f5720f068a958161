"""Python: `# file.mxm:LINE` comments instead of line directives, `math` functions."""

from __future__ import annotations

import keyword
from dataclasses import dataclass

from ..diagnostics import Pos
from ..expr import Add, Expr
from .base import P_ATOM, Language

PY_KEYWORDS = frozenset(keyword.kwlist) | frozenset(keyword.softkwlist) | frozenset(
    {"math", "p", "coefficients", "first_root", "PARAMS", "DEGREE", "NAME"})


@dataclass(frozen=True)
class Python(Language):
    name: str = "python"
    extension: str = ".py"
    keywords: frozenset[str] = PY_KEYWORDS
    terminator: str = ""
    and_op: str = " and "
    functions: tuple[tuple[str, str], ...] = (
        ("sin", "math.sin"), ("cos", "math.cos"), ("tan", "math.tan"), ("sqrt", "math.sqrt"),
        ("exp", "math.exp"), ("log", "math.log"), ("abs", "abs"), ("atan", "math.atan"),
        ("atan2", "math.atan2"), ("asin", "math.asin"), ("acos", "math.acos"),
        ("sinh", "math.sinh"), ("cosh", "math.cosh"), ("tanh", "math.tanh"),
    )

    def join_lines(self, lines: list[str], indent: int) -> str:
        return "(" + super().join_lines(lines, indent) + ")" if len(lines) > 1 else lines[0]

    def power_call(self, base: str, exponent: str) -> str:
        return f"({base})**({exponent})"

    # CPython's compiler fails on a chain of about 3000 additions (RecursionError during
    # compilation: `a + b + ...` nests one level per term), so a longer sum is written as
    # math.fsum of a tuple, which is flat (and exactly rounded).
    long_sum: int = 1000

    def _print(self, e: Expr) -> tuple[str, int]:
        if isinstance(e, Add) and len(e.args) > self.long_sum:
            return f"math.fsum(({', '.join(self.expr(a) for a in e.args)}))", P_ATOM
        return super()._print(e)

    def line_directive(self, pos: Pos) -> str:
        return f"# {self.comment_text(pos.file)}:{pos.line}"

    def comment_text(self, text: str) -> str:
        """Safe in a `#` comment and inside the module's docstring: backslashes and quotes are
        escaped too (a path with `\\N` or `\"\"\"` would otherwise end or break the string)."""
        return super().comment_text(text.replace("\\", "\\\\").replace('"', '\\"'))
