"""An independent oracle: Maxima evaluates the ORIGINAL program at exact rational parameters.

Nothing here uses max2code's coefficient extraction, variants, printers or templates: the
user's program is run as written (through the same guarded Maxima session as everything else),
the parameters are substituted as exact rationals (every double is one), and Maxima expands the
resulting polynomial in t exactly. Its real roots come from mpmath at DIGITS digits, found for
the square-free part p / gcd(p, p') so that every root is simple and converges fully; a root is
a graze (the bodies touch without crossing) when it is also a root of gcd(p, p').

mpmath is the `oracle` extra (`pip install 'max2code[oracle]'`); the tool itself never needs it.
"""

from __future__ import annotations

import re
from fractions import Fraction
from typing import Any, Sequence

from ..maxima import session as maxima, names as maxima_names
from ..diagnostics import Pos, error
from ..front.spec import Spec

DIGITS = 60
# Coefficients are exact rationals, or (with %pi and the like in them) bigfloats of this many
# digits, read as the rationals they print.
BIGFLOAT_DIGITS = 80


def mpmath() -> Any:
    """The mpmath module, or a clear error saying how to install it."""
    try:
        import mpmath as mp
    except ImportError:
        raise error(Pos("max2code", 1, 1), "the oracle needs mpmath: pip install 'max2code[oracle]' "
                    "(or pip install mpmath)") from None
    return mp


def _rational(x: float) -> str:
    f = Fraction(x)
    return f"({f.numerator}/{f.denominator})"


def exact_coefficients(spec: Spec, names: Sequence[str], samples: Sequence[Sequence[float]],
                       timeout: float = maxima.DEFAULT_TIMEOUT) -> list[tuple[Fraction, ...] | None]:
    """For each sample (values of `names`), the exact coefficients of the equation, c[k]
    multiplying t^k; None where Maxima cannot evaluate it there (a division by zero)."""
    t = spec.variable
    # The parameters get the oracle's own names before the program runs: a parameter named
    # like one of Maxima's variables (fpprec, expop) is then a symbol here whatever the
    # generator's checks say (maxima_names), so the oracle cannot share that blind spot.
    mangled = {n: f"o__p{k}" for k, n in enumerate(names)}
    statements = maxima_names.rename(spec.program.statements, mangled)
    own = frozenset(mangled.get(n, n) for n in spec.own_names)
    lines = [maxima.program_script(statements, own, renamed=True),
             "o__e: %$", "o__e: ev(o__e, nouns)$",
             'o__e: if not atom(o__e) and op(o__e) = "=" then lhs(o__e) - rhs(o__e) else o__e$',
             "errormsg: false$", f"fpprec: {BIGFLOAT_DIGITS}$",
             # A coefficient with %pi (or another constant) in it is given to BIGFLOAT_DIGITS.
             "o__num(o__c) := if ratnump(o__c) then o__c else bfloat(o__c)$"]
    for i, sample in enumerate(samples):
        subst = ", ".join(f"{mangled[n]} = {_rational(v)}" for n, v in zip(names, sample))
        lines.append(f"o__x: errcatch(ratexpand(subst([{subst}], o__e)))$")
        lines.append(f'if o__x = [] then printf(true, "~%ORACLE {i} NONE~%") else '
                     f'printf(true, "~%ORACLE {i} ~a~%", string(makelist(o__num(ratcoef('
                     f"first(o__x), {t}, o__k)), o__k, 0, hipow(first(o__x), {t}))))$")
    lines.append(maxima.marker("ORACLE-DONE"))
    session = maxima.run("\n".join(lines) + "\n", spec.program.statements,
                         spec.program.last_pos, timeout)
    found = dict(re.findall(r"^ORACLE (\d+) (.*)$", session.output, re.M))
    if len(found) != len(samples):
        raise error(spec.program.last_pos, "the oracle's Maxima run stopped early")
    out: list[tuple[Fraction, ...] | None] = []
    for i in range(len(samples)):
        text = found[str(i)].strip()
        if text == "NONE" or not (text.startswith("[") and text.endswith("]")):
            out.append(None)
            continue
        try:
            out.append(tuple(Fraction(re.sub(r"[bB]", "e", c.strip()))
                             for c in text[1:-1].split(",")))
        except ValueError:  # not a number: the equation has symbols left at this sample
            out.append(None)
    return out


def _trim(cs: Sequence[Fraction]) -> list[Fraction]:
    out = list(cs)
    while out and out[-1] == 0:
        out.pop()
    return out


def _rem(a: list[Fraction], b: list[Fraction]) -> list[Fraction]:
    a = _trim(a)
    while len(a) >= len(b):
        q = a[-1] / b[-1]
        shift = len(a) - len(b)
        for i, bc in enumerate(b):
            a[shift + i] -= q * bc
        a = _trim(a[:-1])
    return a


def gcd_poly(a: Sequence[Fraction], b: Sequence[Fraction]) -> list[Fraction]:
    x, y = _trim(a), _trim(b)
    while y:
        x, y = y, _rem(x, y)
    return x


def _div(a: Sequence[Fraction], b: list[Fraction]) -> list[Fraction]:
    """The exact quotient a / b (b divides a)."""
    rest = _trim(a)
    q = [Fraction(0)] * (len(rest) - len(b) + 1)
    while len(rest) >= len(b):
        shift = len(rest) - len(b)
        q[shift] = rest[-1] / b[-1]
        for i, bc in enumerate(b):
            rest[shift + i] -= q[shift] * bc
        rest = _trim(rest[:-1])
    assert not rest, "not a divisor"
    return q


def derivative(cs: Sequence[Fraction]) -> list[Fraction]:
    return [k * c for k, c in enumerate(cs)][1:]


def real_roots(cs: Sequence[Fraction], tmax: float) -> list[Any]:
    """The distinct real roots in (0, tmax] of the exact polynomial, ascending, as mpmath
    numbers at DIGITS digits."""
    mp = mpmath()
    mp.mp.dps = DIGITS
    poly = _trim(cs)
    g = gcd_poly(poly, derivative(poly))
    if len(g) >= 2:
        poly = _div(poly, g)
    while poly and poly[0] == 0:
        poly.pop(0)
    if len(poly) < 2:
        return []
    values = [mp.mpf(c.numerator) / c.denominator for c in reversed(poly)]
    roots = mp.polyroots(values, maxsteps=800, extraprec=800)
    found: list[Any] = []
    for r in roots:
        re_, im = mp.re(r), mp.im(r)
        if abs(im) <= mp.mpf(10) ** -40 * max(1, abs(re_)) and 0 < re_ <= tmax:
            if not any(abs(re_ - f) <= mp.mpf(10) ** -35 * max(1, abs(re_)) for f in found):
                found.append(re_)
    return sorted(found)


def is_multiple(cs: Sequence[Fraction], root: Any) -> bool:
    """Whether `root` is a multiple root: a root of gcd(p, p') (exact arithmetic)."""
    mp = mpmath()
    g = gcd_poly(cs, derivative(cs))
    if len(g) < 2:
        return False
    value = mp.polyval([mp.mpf(c.numerator) / c.denominator for c in reversed(g)], root)
    size = sum(abs(mp.mpf(c.numerator) / c.denominator) * abs(root) ** k
               for k, c in enumerate(g))
    return bool(abs(value) <= mp.mpf(10) ** -30 * size)


def first_root(cs: Sequence[Fraction], tmax: float) -> tuple[Any | None, bool]:
    """(the smallest real root in (0, tmax] or None, whether it is a graze)."""
    roots = real_roots(cs, tmax)
    if not roots:
        return None, False
    return roots[0], is_multiple(cs, roots[0])
