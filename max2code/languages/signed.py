"""The sign rules Modula-2 and Rust share, kept apart from either language's folder so that
neither imports from the other."""

from __future__ import annotations

from ..codegen.expr import Add, Expr, Neg, Num
from .base import P_ADD, P_MUL, P_NEG, Language


class SignedOperands(Language):
    """Sign rules for languages where a sign only begins an expression (Modula-2's grammar) or
    where a sign after an operator reads badly and lints (Rust: `a + -b`, `a/-b`, clippy's
    `double_neg` on `--x`). A signed operand is parenthesised; a signed addend becomes a
    subtraction, which is the same number (negation is exact)."""

    def _print(self, e: Expr) -> tuple[str, int]:
        """A signed operand binds like a sum: wherever a term is needed, it gets parentheses."""
        text, prec = self._signed(e)
        return (text, P_ADD) if prec == P_NEG else (text, prec)

    def _signed(self, e: Expr) -> tuple[str, int]:
        """Like the shared printer, but a sum's later addends are never signed: `a + -b*c` is
        written `a - b*c`."""
        if isinstance(e, Neg):
            text, prec = self._signed(e.arg)
            return "-" + (text if P_MUL <= prec != P_NEG else f"({text})"), P_NEG
        if not isinstance(e, Add):
            return super()._print(e)
        parts = [self._wrap(e.args[0], P_ADD)]
        for arg in e.args[1:]:
            if isinstance(arg, Neg):
                text, prec = self._signed(arg.arg)
                parts.append(" - " + (text if P_MUL <= prec != P_NEG else f"({text})"))
                continue
            if isinstance(arg, Num) and arg.value < 0:
                parts.append(" - " + self.number(-arg.value))
                continue
            text, prec = self._signed(arg)
            if prec == P_NEG:  # always "-" followed by a term
                parts.append(" - " + text[1:])
            elif prec > P_ADD:
                parts.append(" + " + text)
            else:
                parts.append(f" + ({text})")
        return "".join(parts), P_ADD
