"""The optimised strategy: evaluate Maxima's unexpanded equation as a polynomial in t.

Every node of the expression tree becomes a list of coefficients (index = power of t) whose
entries are expressions in the parameters, built through a `Builder` so that they are shared
and so that differences between bodies are formed first. Only the variable is expanded: a
square of a sum becomes the convolution of the sum's coefficients, never a sum of products of
positions. Maxima's degree is authoritative: coefficients above it are identically zero.
"""

from __future__ import annotations

from .expr import ZERO, Add, Call, Div, Expr, Float, Mul, Neg, Num, Pow, Ref, Sym
from .straight import Builder, Straight, neg, prune

TPoly = list[Expr]


class NotPolynomial(ValueError):
    """The unexpanded form uses t where only a constant can be (e.g. inside a function)."""


def optimise(e: Expr, variable: str, degree: int, prefix: str = "m2c_t") -> Straight:
    b = Builder(prefix)
    coefs = _eval(e, variable, b)
    coefs = [b.intern(c) if not isinstance(c, Neg) else neg(b.intern(c.arg)) for c in coefs]
    outputs = tuple((coefs + [ZERO] * (degree + 1))[: degree + 1])
    return Straight(prune(b.temps, outputs), outputs)


def _eval(e: Expr, t: str, b: Builder) -> TPoly:
    if isinstance(e, Sym):
        return [ZERO, Num(1)] if e.name == t else [e]  # type: ignore[arg-type]
    if isinstance(e, (Num, Float, Ref)):
        return [e]
    if isinstance(e, Neg):
        return [neg(c) for c in _eval(e.arg, t, b)]
    if isinstance(e, Add):
        parts = [_eval(arg, t, b) for arg in e.args]
        size = max(len(p) for p in parts)
        return [b.intern(b.add([p[k] for p in parts if k < len(p)])) for k in range(size)]
    if isinstance(e, Mul):
        scalars: list[Expr] = []
        polys: list[TPoly] = []
        for arg in e.args:
            p = _eval(arg, t, b)
            (scalars.append(p[0]) if len(p) == 1 else polys.append(p))
        scale: Expr = Num(1)  # type: ignore[arg-type]
        for s in scalars:
            scale = b.intern(b.mul(scale, s))
        if not polys:
            return [scale]
        result = polys[0]
        for p in polys[1:]:
            result = _convolve(result, p, b)
        return [b.intern(b.mul(scale, c)) for c in result]
    if isinstance(e, Div):
        den = _eval(e.den, t, b)
        if len(den) != 1:
            raise NotPolynomial("the variable is in a denominator")
        return [b.intern(b.div(c, den[0])) for c in _eval(e.num, t, b)]
    if isinstance(e, Pow):
        exp = _eval(e.exp, t, b)
        base = _eval(e.base, t, b)
        if len(exp) != 1:
            raise NotPolynomial("the variable is in an exponent")
        n = exp[0]
        if len(base) == 1:
            if isinstance(n, Num) and n.value.denominator == 1 and n.value >= 0:
                return [b.power(base[0], int(n.value))]
            return [b.intern(Pow(base[0], n))]
        if not (isinstance(n, Num) and n.value.denominator == 1 and n.value >= 0):
            raise NotPolynomial("a power of the variable that is not a whole number")
        return _power(base, int(n.value), b)
    if isinstance(e, Call):
        args = [_eval(a, t, b) for a in e.args]
        if any(len(a) != 1 for a in args):
            raise NotPolynomial(f"the variable is inside {e.name}(...)")
        return [b.intern(Call(e.name, tuple(a[0] for a in args)))]
    raise TypeError(f"unexpected node {e!r}")


def _convolve(p: TPoly, q: TPoly, b: Builder) -> TPoly:
    out = []
    for k in range(len(p) + len(q) - 1):
        terms = [b.mul(p[i], q[k - i]) for i in range(len(p)) if 0 <= k - i < len(q)]
        out.append(b.intern(b.add([x for x in terms if x != ZERO])))
    return out


def _square(p: TPoly, b: Builder) -> TPoly:
    """(sum a_i t^i)^2: each cross product once, doubled: about half the work of a product."""
    out = []
    for k in range(2 * len(p) - 1):
        cross = [b.mul(p[i], p[k - i]) for i in range(len(p)) if i < k - i < len(p)]
        cross = [x for x in cross if x != ZERO]
        terms: list[Expr] = []
        if cross:
            terms.append(b.mul(Num(2), b.intern(b.add(cross))))  # type: ignore[arg-type]
        if k % 2 == 0 and p[k // 2] != ZERO:
            terms.append(b.power(p[k // 2], 2))
        out.append(b.intern(b.add(terms)))
    return out


def _power(p: TPoly, n: int, b: Builder) -> TPoly:
    if n == 0:
        return [Num(1)]  # type: ignore[list-item]
    if n == 1:
        return p
    half = _square(_power(p, n // 2, b), b)
    return half if n % 2 == 0 else _convolve(half, p, b)
