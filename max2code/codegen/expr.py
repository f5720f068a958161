"""Expression trees for Maxima's output, and the parser that builds them.

Maxima prints each coefficient in its one-dimensional syntax (display2d:false, string()); we
parse that subset properly instead of pattern-matching `coef*t^k` in a printed sum, which is how
the original tool lost factors, denominators and powers. The subset, loosest first:

    sum     := product (("+" | "-") product)*
    product := unary (("*" | "/") unary)*
    unary   := "-" unary | "+" unary | power
    power   := atom ["^" unary]                       (so a^b^c is a^(b^c), a^-b is allowed)
    atom    := NUMBER | SYMBOL | ["'"] SYMBOL "(" [sum ("," sum)*] ")" | "(" sum ")"

The parser is an operator-precedence (shunting-yard) loop over regular-expression tokens: no
recursion, so neither a sum of 100,000 terms nor deep nesting can exhaust Python's stack, and
about twenty times faster than the Lark grammar it replaces on long coefficients.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from fractions import Fraction
from typing import Iterator, Union


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


# How deeply Maxima's output may nest (parentheses, powers, signs, calls). Sums and products
# are flat whatever their length; every later stage walks nesting recursively (the printers,
# the optimiser, dataclass hashing), so it is bounded here, far above any real equation, with a
# diagnostic instead of Python's RecursionError.
MAX_DEPTH = 120


class _Chain(list):  # type: ignore[type-arg]
    """An n-ary sum or product still growing: the grammar is left-recursive, and appending
    here keeps a sum of n terms linear to build (a tuple copied at each term would be n^2)."""

    def __init__(self, kind: type, items: list) -> None:
        super().__init__(items)
        self.kind = kind


def _done(e: object) -> Expr:
    """A finished node: a chain becomes its Add or Mul."""
    if isinstance(e, _Chain):
        return e.kind(tuple(_done(x) for x in e))  # type: ignore[no-any-return]
    return e  # type: ignore[return-value]


def _extend(kind: type, left: object, right: Expr) -> _Chain:
    if isinstance(left, _Chain) and left.kind is kind:
        left.append(right)
        return left
    if isinstance(left, kind):  # a finished sum in parentheses is flattened like before
        return _Chain(kind, [*left.args, right])  # type: ignore[attr-defined]
    return _Chain(kind, [_done(left), right])


_TOKEN = re.compile(r"""\s*(?:
    (?P<num>[0-9]+(?:\.[0-9]*)?(?:[eEbB][+-]?[0-9]+)?|\.[0-9]+(?:[eEbB][+-]?[0-9]+)?)
  | (?P<call>'?%?[A-Za-z_][A-Za-z_0-9]*(?=\s*\())
  | (?P<sym>%?[A-Za-z_][A-Za-z_0-9]*)
  | (?P<op>[-+*/^(),])
  | (?P<end>\Z)
  | (?P<bad>.)
)""", re.X | re.S)

# Binding strength of the binary operators, and whether they group to the right.
_BINARY = {"+": (1, False), "-": (1, False), "*": (2, False), "/": (2, False), "^": (4, True)}
_UNARY = 3  # a sign binds tighter than * and looser than ^ (-a^2 is -(a^2))


def _number(text: str) -> Expr:
    if any(ch in text for ch in ".eEbB"):
        return Float(text)
    return Num(Fraction(int(text)))


def _apply(op: str, out: list) -> None:
    """Replace the operands on top of `out` by `op` applied to them."""
    if op == "neg" or op == "pos":
        arg = _done(out.pop())
        if op == "neg":
            arg = Num(-arg.value) if isinstance(arg, Num) else Neg(arg)
        out.append(arg)
        return
    right = _done(out.pop())
    left = out.pop()
    if op == "+":
        out.append(_extend(Add, left, right))
    elif op == "-":
        out.append(_extend(Add, left, Neg(right)))
    elif op == "*":
        out.append(_extend(Mul, left, right))
    elif op == "/":
        num = _done(left)
        if isinstance(num, Num) and isinstance(right, Num) and right.value != 0:
            out.append(Num(num.value / right.value))
        else:
            out.append(Div(num, right))
    else:
        out.append(Pow(_done(left), right))


def _parse(text: str) -> Expr:
    out: list = []  # operands (and growing sums/products)
    ops: list = []  # operators; ("(",) and ("call", name, out-length) open a group
    operand = True  # whether an operand is expected next
    for m in _TOKEN.finditer(text):
        kind = m.lastgroup or "bad"
        tok = m.group(kind)
        if kind == "bad" or (kind == "end" and operand):
            where = "end" if kind == "end" else f"{tok!r} at offset {m.start(kind)}"
            raise ExprSyntaxError(f"unexpected {where}")
        if kind == "end":
            break
        if operand:
            if kind == "num":
                out.append(_number(tok))
                operand = False
            elif kind == "sym":
                out.append(Sym(tok))
                operand = False
            elif kind == "call":  # its "(" comes next (the pattern looked ahead for it)
                ops.append(("call", tok.lstrip("'"), len(out)))
            elif tok in "-+":
                ops.append(("neg" if tok == "-" else "pos",))
            elif tok == "(":
                ops.append(("(",))
            elif tok == ")" and ops and ops[-1] == ("(",) and len(ops) > 1 and ops[-2][0] == "call" \
                    and ops[-2][2] == len(out):
                ops.pop()
                _, name, _ = ops.pop()
                out.append(Call(name, ()))
                operand = False
            else:
                raise ExprSyntaxError(f"unexpected {tok!r} at offset {m.start(kind)}")
            continue
        if tok in _BINARY:
            prec, right = _BINARY[tok]
            while ops and ops[-1][0] not in ("(", "call") and (
                    _strength(ops[-1][0]) > prec or (_strength(ops[-1][0]) == prec and not right)):
                _apply(ops.pop()[0], out)
            ops.append((tok,))
            operand = True
        elif tok in ",)":
            while ops and ops[-1] != ("(",):
                _apply(ops.pop()[0], out)
            if not ops:
                raise ExprSyntaxError(f"unexpected {tok!r} at offset {m.start(kind)}")
            call = ops[-2] if len(ops) > 1 and ops[-2][0] == "call" else None
            if tok == ",":
                if call is None:
                    raise ExprSyntaxError(f"unexpected ',' at offset {m.start(kind)}")
                operand = True
                continue
            ops.pop()
            if call is not None:
                ops.pop()
                args = [_done(a) for a in out[call[2]:]]
                del out[call[2]:]
                out.append(Call(call[1], tuple(args)))
        else:
            raise ExprSyntaxError(f"unexpected {tok!r} at offset {m.start(kind)}")
    while ops:
        op = ops.pop()[0]
        if op in ("(", "call"):
            raise ExprSyntaxError("unbalanced parenthesis")
        _apply(op, out)
    if len(out) != 1:
        raise ExprSyntaxError("not one expression")
    return _done(out[0])


def _strength(op: str) -> int:
    return _UNARY if op in ("neg", "pos") else _BINARY[op][0]


class ExprSyntaxError(ValueError):
    """Maxima printed something outside the subset we understand, or nested too deeply."""


def parse_maxima(text: str) -> Expr:
    try:
        e = _parse(text)
    except ExprSyntaxError as exc:
        raise ExprSyntaxError(f"cannot read Maxima output {text[:80]!r}: {exc}") from None
    nesting = depth(e)
    if nesting > MAX_DEPTH:
        raise ExprSyntaxError(f"Maxima's result is nested {nesting} levels deep (parentheses, "
                              f"powers, signs, function calls); max2code handles at most "
                              f"{MAX_DEPTH}: simplify it (for example with expand or ratsimp)")
    return e


def depth(e: Expr) -> int:
    """How deeply an expression nests (a symbol: 1), without recursion."""
    deepest = 0
    stack = [(e, 1)]
    while stack:
        node, level = stack.pop()
        deepest = max(deepest, level)
        stack.extend((child, level + 1) for child in children(node))
    return deepest


def _walk(e: Expr) -> Iterator[Expr]:
    """Every node of an expression, without recursion."""
    stack = [e]
    while stack:
        node = stack.pop()
        yield node
        stack.extend(children(node))


def symbols(e: Expr) -> set[str]:
    """Names of the free symbols (not functions) in an expression."""
    return {node.name for node in _walk(e) if isinstance(node, Sym)}


def calls(e: Expr) -> set[str]:
    """Names of the functions an expression calls."""
    return {node.name for node in _walk(e) if isinstance(node, Call)}


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
