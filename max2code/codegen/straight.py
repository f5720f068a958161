"""Straight-line code: named temporaries (shared subexpressions) and the outputs that use them.

Both evaluation strategies end here. `expanded` has no temporaries: each coefficient is Maxima's
fully expanded sum. `optimised` (tpoly.py) builds temporaries through a `Builder`, whose small
algebra folds constants, shares identical subexpressions, and sums like quantities of different
bodies first (`x1 - x2` before anything else is added), which is what keeps digits when two
bodies are far from the origin and close to each other.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from fractions import Fraction

from .expr import ZERO, Add, Call, Div, Expr, Float, Mul, Neg, Num, Pow, Ref, Sym, children

ONE = Num(Fraction(1))


@dataclass(frozen=True)
class Ops:
    add: int = 0
    mul: int = 0
    div: int = 0
    call: int = 0

    @property
    def total(self) -> int:
        return self.add + self.mul + self.div + self.call

    def __add__(self, other: Ops) -> Ops:
        return Ops(self.add + other.add, self.mul + other.mul, self.div + other.div,
                   self.call + other.call)


@dataclass(frozen=True)
class Straight:
    """`temps` are computed in order (each may use earlier ones); `outputs[k]` multiplies t^k."""

    temps: tuple[tuple[str, Expr], ...]
    outputs: tuple[Expr, ...]

    @property
    def ops(self) -> Ops:
        total = Ops()
        for _, e in self.temps:
            total = total + count_ops(e)
        for e in self.outputs:
            total = total + count_ops(e)
        return total


def count_ops(e: Expr) -> Ops:
    """Floating-point operations as the printers write them (x^n as n-1 multiplications)."""
    own = Ops()
    if isinstance(e, Add):
        own = Ops(add=len(e.args) - 1)
    elif isinstance(e, Mul):
        factors = [f for f in e.args if not (isinstance(f, Num) and abs(f.value) == 1)]
        own = Ops(mul=max(len(factors) - 1, 0))
    elif isinstance(e, Div):
        own = Ops(div=1)
    elif isinstance(e, Pow):
        if isinstance(e.exp, Num) and e.exp.value.denominator == 1:
            n = abs(e.exp.value.numerator)
            own = Ops(mul=max(n - 1, 0), div=1 if e.exp.value < 0 else 0)
            return own + count_ops(e.base)
        own = Ops(call=1)
    elif isinstance(e, Call):
        own = Ops(call=1)
    total = own
    for child in children(e):
        total = total + count_ops(child)
    return total


def _stem(name: str) -> str:
    """`vx1` and `vx2` are the same quantity of two bodies: the name without trailing digits."""
    return re.sub(r"\d+$", "", name)


class Builder:
    """Collects temporaries; every non-trivial expression is stored once and referred to."""

    def __init__(self, prefix: str = "m2c_t") -> None:
        self.prefix = prefix
        self.temps: list[tuple[str, Expr]] = []
        self._index: dict[Expr, Ref] = {}
        self._family: dict[str, tuple[str, ...]] = {}

    # ---- sharing ----------------------------------------------------------------------------
    def intern(self, e: Expr) -> Expr:
        if isinstance(e, (Num, Float, Sym, Ref)):
            return e
        if isinstance(e, Neg):
            return neg(self.intern(e.arg))
        found = self._index.get(e)
        if found is not None:
            return found
        ref = Ref(f"{self.prefix}{len(self.temps)}")
        self.temps.append((ref.name, e))
        self._index[e] = ref
        self._family[ref.name] = self.family(e)
        return ref

    def family(self, e: Expr) -> tuple[str, ...]:
        """The kinds of quantity an expression is made of, bodies not told apart."""
        if isinstance(e, Sym):
            return (_stem(e.name),)
        if isinstance(e, Ref):
            return self._family.get(e.name, ())
        out: set[str] = set()
        for child in children(e):
            out.update(self.family(child))
        return tuple(sorted(out))

    # ---- algebra ----------------------------------------------------------------------------
    def add(self, terms: list[Expr]) -> Expr:
        """A sum, with like quantities of different bodies summed first (relative quantities)."""
        constant = Fraction(0)
        groups: dict[tuple[str, ...], list[Expr]] = {}
        for term in terms:
            if isinstance(term, Num):
                constant += term.value
            else:
                groups.setdefault(self.family(term), []).append(term)
        parts: list[Expr] = []
        for key in sorted(groups):
            members = sorted(groups[key], key=lambda x: isinstance(x, Neg))  # a - b, not -b + a
            parts.append(members[0] if len(members) == 1 else self.intern(Add(tuple(members))))
        if constant:
            parts.append(Num(constant))
        if not parts:
            return ZERO
        if len(parts) == 1:
            return parts[0]
        if isinstance(parts[0], Neg) and any(not isinstance(p, Neg) for p in parts):
            first = next(p for p in parts if not isinstance(p, Neg))
            parts.remove(first)
            parts.insert(0, first)
        return Add(tuple(parts))

    def mul(self, a: Expr, b: Expr) -> Expr:
        if a == ZERO or b == ZERO:
            return ZERO
        if isinstance(a, Num) and isinstance(b, Num):
            return Num(a.value * b.value)
        if isinstance(a, Neg):
            return neg(self.mul(a.arg, b))
        if isinstance(b, Neg):
            return neg(self.mul(a, b.arg))
        if isinstance(a, Num) and a.value < 0:
            return neg(self.mul(Num(-a.value), b))
        if isinstance(b, Num) and b.value < 0:
            return neg(self.mul(a, Num(-b.value)))
        if a == ONE:
            return b
        if b == ONE:
            return a
        if isinstance(b, Num):
            a, b = b, a
        return Mul((a, b))

    def div(self, a: Expr, den: Expr) -> Expr:
        if a == ZERO:
            return ZERO
        if isinstance(den, Num):
            if isinstance(a, Num):
                return Num(a.value / den.value)
            inverse = 1 / den.value
            if inverse.numerator == 1 and (inverse.denominator & (inverse.denominator - 1)) == 0:
                return self.mul(Num(abs(inverse)), a) if inverse > 0 else neg(self.mul(Num(-inverse), a))
            if abs(den.value) == 1:
                return a if den.value > 0 else neg(a)
        if isinstance(a, Neg):
            return neg(self.div(a.arg, den))
        return Div(a, den)

    def power(self, x: Expr, n: int) -> Expr:
        """x^n by squaring, each square shared: w^4 is (w*w)*(w*w) computed as two products."""
        if n == 0:
            return ONE
        if n == 1:
            return x
        if isinstance(x, Num):
            return Num(x.value ** n)
        if isinstance(x, Neg):
            inner = self.power(x.arg, n)
            return neg(inner) if n % 2 else inner
        half = self.power(x, n // 2)
        square = self.intern(Mul((half, half)))
        return square if n % 2 == 0 else self.intern(Mul((square, x)))


def neg(e: Expr) -> Expr:
    if isinstance(e, Neg):
        return e.arg
    if isinstance(e, Num):
        return Num(-e.value)
    if e == ZERO:
        return e
    return Neg(e)


def prune(temps: list[tuple[str, Expr]], outputs: tuple[Expr, ...]) -> tuple[tuple[str, Expr], ...]:
    """Only the temporaries the outputs need (coefficients Maxima proved zero are dropped)."""
    needed: set[str] = set()

    def visit(e: Expr) -> None:
        if isinstance(e, Ref):
            needed.add(e.name)
        for child in children(e):
            visit(child)

    for e in outputs:
        visit(e)
    for name, e in reversed(temps):
        if name in needed:
            visit(e)
    return tuple((name, e) for name, e in temps if name in needed)
