"""Expression trees for Maxima's output, and the parser that builds them.

Maxima prints each coefficient in its one-dimensional syntax; we parse that with a grammar of our
own (maxima_expr.lark) instead of pattern-matching `coef*t^k` in a printed sum, which is how the
original tool lost factors, denominators and powers.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache
from importlib import resources
from typing import Union

from lark import Lark, Transformer
from lark.exceptions import LarkError


@dataclass(frozen=True)
class Num:
    """An exact rational (Maxima integers and p/q)."""

    value: Fraction


@dataclass(frozen=True)
class Float:
    """A floating-point literal as Maxima printed it (e.g. 1.5e-3 or a bigfloat 1.5b0)."""

    text: str

    @property
    def value(self) -> float:
        return float(self.text.replace("b", "e").replace("B", "e"))


@dataclass(frozen=True)
class Sym:
    name: str


@dataclass(frozen=True)
class Neg:
    arg: Expr


@dataclass(frozen=True)
class Add:
    args: tuple[Expr, ...]


@dataclass(frozen=True)
class Mul:
    args: tuple[Expr, ...]


@dataclass(frozen=True)
class Div:
    num: Expr
    den: Expr


@dataclass(frozen=True)
class Pow:
    base: Expr
    exp: Expr


@dataclass(frozen=True)
class Call:
    name: str
    args: tuple[Expr, ...]


@dataclass(frozen=True)
class Ref:
    """A temporary of generated straight-line code (a shared subexpression), printed verbatim."""

    name: str


Expr = Union[Num, Float, Sym, Neg, Add, Mul, Div, Pow, Call, Ref]

ZERO = Num(Fraction(0))


class _ToExpr(Transformer):  # type: ignore[type-arg]
    def number(self, items: list) -> Expr:
        text = str(items[0])
        if any(ch in text for ch in ".eEbB"):
            return Float(text)
        return Num(Fraction(int(text)))

    def symbol(self, items: list) -> Expr:
        return Sym(str(items[0]))

    def call(self, items: list) -> Expr:
        return Call(str(items[0]), tuple(a for a in items[1:] if a is not None))

    def add(self, items: list) -> Expr:
        left, right = items
        return Add(_flat(left, Add) + (right,))

    def sub(self, items: list) -> Expr:
        left, right = items
        return Add(_flat(left, Add) + (Neg(right),))

    def mul(self, items: list) -> Expr:
        left, right = items
        return Mul(_flat(left, Mul) + (right,))

    def div(self, items: list) -> Expr:
        num, den = items
        if isinstance(num, Num) and isinstance(den, Num) and den.value != 0:
            return Num(num.value / den.value)
        return Div(num, den)

    def neg(self, items: list) -> Expr:
        (arg,) = items
        if isinstance(arg, Num):
            return Num(-arg.value)
        return Neg(arg)

    def pow(self, items: list) -> Expr:
        base, exp = items
        return Pow(base, exp)


def _flat(e: Expr, kind: type) -> tuple[Expr, ...]:
    return e.args if isinstance(e, kind) else (e,)  # type: ignore[union-attr]


@lru_cache(maxsize=1)
def _parser() -> Lark:
    grammar = resources.files(__package__).joinpath("maxima_expr.lark").read_text(encoding="utf-8")
    return Lark(grammar, start="sum", parser="lalr")


class ExprSyntaxError(ValueError):
    """Maxima printed something outside the subset we understand."""


def parse_maxima(text: str) -> Expr:
    try:
        return _ToExpr().transform(_parser().parse(text))  # type: ignore[no-any-return]
    except LarkError as exc:
        raise ExprSyntaxError(f"cannot read Maxima output {text[:80]!r}: "
                              f"{str(exc).splitlines()[0]}") from None


def symbols(e: Expr) -> set[str]:
    """Names of the free symbols (not functions) in an expression."""
    if isinstance(e, Sym):
        return {e.name}
    out: set[str] = set()
    for child in children(e):
        out |= symbols(child)
    return out


def calls(e: Expr) -> set[str]:
    """Names of the functions an expression calls."""
    out = {e.name} if isinstance(e, Call) else set()
    for child in children(e):
        out |= calls(child)
    return out


def children(e: Expr) -> tuple[Expr, ...]:
    if isinstance(e, (Add, Mul, Call)):
        return e.args
    if isinstance(e, Neg):
        return (e.arg,)
    if isinstance(e, Div):
        return (e.num, e.den)
    if isinstance(e, Pow):
        return (e.base, e.exp)
    return ()
