"""Hard cases for the smallest-positive-root runtimes, as data, plus an oracle.

Shared by the C, Python and Rust runtime tests, so this module is plain data
and pure functions: importing it does nothing but define them.

Every case is a polynomial ``c[0] + c[1] t + ... + c[n] t^n`` with double
coefficients and a window ``(0, tmax]``.  The truth is always computed from
the *double* coefficients (what the runtime actually receives), never from the
roots the case was built from: rounding the coefficients moves the roots, and a
runtime cannot be blamed for that.  ``oracle()`` does this at 60 digits.

Error bounds are relative errors of the first root against the oracle, per
method.  A method missing from ``Case.bounds`` is not asserted on that case;
the comment next to the case says why (typically: GSL's companion matrix is
backward stable for the matrix, not for the coefficients, so spread or
clustered roots lose digits).
"""
from __future__ import annotations

import math
import random
from dataclasses import dataclass, field
from fractions import Fraction
from functools import lru_cache
from typing import Iterable, Iterator, Mapping, Sequence

import mpmath

U = 2.0**-53  # unit roundoff of binary64

# Methods as named by the Python runtime; the C test maps them to numbers.
METHODS = ("interval", "interval-nograze", "closed", "gsl")


@dataclass(frozen=True)
class Case:
    """One polynomial with its window and what each method must achieve.

    expect: "root" (a first root in the window; bounds apply),
            "graze" (the first root is a touching double root: the grazing
                     methods must report it, flagged; see Oracle.kind),
            "none" (no root in (0, tmax]), "invalid" (status -1).
    bounds: method -> max relative error of the first root.
    """

    name: str
    family: str
    coeffs: tuple[float, ...]
    tmax: float = math.inf
    expect: str = "root"
    bounds: Mapping[str, float] = field(default_factory=dict)
    note: str = ""


# ---------------------------------------------------------------------------
# Building polynomials exactly
# ---------------------------------------------------------------------------

Num = Fraction | int | str


def _frac(x: Num | float) -> Fraction:
    return x if isinstance(x, Fraction) else Fraction(x)


def poly_from_roots(
    real: Sequence[Num | float] = (),
    pairs: Sequence[tuple[Num | float, Num | float]] = (),
    lead: Num | float = 1,
) -> tuple[float, ...]:
    """Coefficients (low first) of lead * prod (t - r) * prod |t - z|^2,
    multiplied out exactly in rationals and rounded once to double, as the
    TOMS 1010 paper does (it multiplies out at high precision).  Roots given
    as strings are exact decimals ("1E9", "2.003")."""
    c = [_frac(lead)]
    factors = [[-_frac(r), Fraction(1)] for r in real]
    for re, im in pairs:
        a, b = _frac(re), _frac(im)
        factors.append([a * a + b * b, -2 * a, Fraction(1)])
    for f in factors:
        out = [Fraction(0)] * (len(c) + len(f) - 1)
        for i, x in enumerate(c):
            for j, y in enumerate(f):
                out[i + j] += x * y
        c = out
    return tuple(float(x) for x in c)


def mirror(c: Sequence[float]) -> tuple[float, ...]:
    """p(-t): negative roots become positive (exact: sign flips only)."""
    return tuple(-x if i % 2 else x for i, x in enumerate(c))


# ---------------------------------------------------------------------------
# The oracle
# ---------------------------------------------------------------------------

Poly = list[Fraction]  # low first


def _trim(p: Poly) -> Poly:
    while len(p) > 1 and p[-1] == 0:
        p = p[:-1]
    return p


def _deriv(p: Poly) -> Poly:
    return _trim([i * p[i] for i in range(1, len(p))] or [Fraction(0)])


def _divmod(a: Poly, b: Poly) -> tuple[Poly, Poly]:
    a = list(a)
    q = [Fraction(0)] * max(1, len(a) - len(b) + 1)
    while len(a) >= len(b) and any(a):
        k = len(a) - len(b)
        f = a[-1] / b[-1]
        q[k] = f
        for i, y in enumerate(b):
            a[i + k] -= f * y
        a = _trim(a[:-1]) if len(a) > 1 else [Fraction(0)]
    return _trim(q), _trim(a)


def _is_zero(p: Poly) -> bool:
    return all(x == 0 for x in p)


def _gcd(a: Poly, b: Poly) -> Poly:
    while not _is_zero(b):
        a, b = b, _divmod(a, b)[1]
    return [x / a[-1] for x in a]


def _yun(p: Poly) -> list[Poly]:
    """Square-free factorisation: returns a_1, a_2, ... with p ~ prod a_i^i."""
    d = _deriv(p)
    a0 = _gcd(p, d)
    b = _divmod(p, a0)[0]
    c = _divmod(d, a0)[0]
    out: list[Poly] = []
    while len(b) > 1:
        dd = [x - y for x, y in zip(c + [Fraction(0)] * len(b), _deriv(b) + [Fraction(0)] * len(c))]
        dd = _trim(dd)
        a = _gcd(b, dd) if not _is_zero(dd) else b
        out.append(a)
        b = _divmod(b, a)[0]
        c = _divmod(dd, a)[0] if not _is_zero(dd) else [Fraction(0)]
    return out


class _Sturm:
    """Sturm sequence of a square-free polynomial: exact counts of distinct
    real roots in (lo, hi]."""

    def __init__(self, p: Poly) -> None:
        seq = [p, _deriv(p)]
        while len(seq[-1]) > 1:
            r = _divmod(seq[-2], seq[-1])[1]
            if _is_zero(r):
                break
            seq.append([-x for x in r])
        self.seq = seq

    def _changes(self, x: Fraction | None) -> int:
        signs = []
        for q in self.seq:
            if x is None:
                v = q[-1]
            else:
                v = Fraction(0)
                for coef in reversed(q):
                    v = v * x + coef
            if v != 0:
                signs.append(v > 0)
        return sum(1 for s, t in zip(signs, signs[1:]) if s != t)

    def count(self, lo: Fraction, hi: Fraction | None) -> int:
        return self._changes(lo) - self._changes(hi)


def _mpf_to_fraction(x: mpmath.mpf) -> Fraction:
    man, exp = mpmath.mpf(x).man_exp
    return Fraction(int(man)) * (Fraction(2) ** int(exp))


def _cauchy_bound(p: Poly) -> Fraction:
    return 1 + max(abs(x / p[-1]) for x in p[:-1])


def _split(lo: Fraction, hi: Fraction) -> Fraction:
    """A point strictly inside (lo, hi): geometric when the bracket spans
    decades (roots near 0 are then isolated in few steps)."""
    flo, fhi = float(lo), float(hi)
    if flo > 0 and fhi > 8 * flo:
        mid = Fraction(math.sqrt(flo) * math.sqrt(fhi))
    elif flo == 0 and fhi > 0:
        mid = Fraction(fhi / 2**20)
    else:
        mid = (lo + hi) / 2
    return mid if lo < mid < hi else (lo + hi) / 2


def _mp_eval(p: Poly, x: mpmath.mpf) -> mpmath.mpf:
    v = mpmath.mpf(0)
    for coef in reversed(p):
        v = v * x + mpmath.mpf(coef.numerator) / coef.denominator
    return v


def _first_real_root(a: Poly, hint: list[mpmath.mpf], hi: Fraction | None) -> mpmath.mpf | None:
    """Smallest root of square-free a in (0, hi], to 60 digits, proved by
    Sturm counts: the polyroots hint is accepted when the counts confirm it,
    else the root is isolated by exact bisection and refined in mpmath."""
    st = _Sturm(a)
    total = st.count(Fraction(0), hi)
    if total == 0:
        return None
    eps = Fraction(1, 10**45)
    for r in sorted(x for x in hint if x > 0):
        fr = _mpf_to_fraction(r)
        lo_, hi_ = fr * (1 - eps), fr * (1 + eps)
        if st.count(Fraction(0), lo_) == 0 and st.count(lo_, hi_) == 1:
            return r
        break
    lo = Fraction(0)
    top = hi if hi is not None else _cauchy_bound(a)
    for _ in range(4000):
        if st.count(lo, top) == 1:
            break
        mid = _split(lo, top)
        if st.count(lo, mid) >= 1:
            top = mid
        else:
            lo = mid
    # one simple root in (lo, top]: it changes sign there; bisect in mpmath
    with mpmath.workdps(80):
        x0, x1 = mpmath.mpf(lo.numerator) / lo.denominator, mpmath.mpf(top.numerator) / top.denominator
        f0 = _mp_eval(a, x0)
        if _mp_eval(a, x1) == 0:
            return +x1
        for _ in range(2000):
            if x1 - x0 <= x1 * mpmath.mpf(10) ** -70:
                break
            if x0 > 0 and x1 > 8 * x0:
                m = mpmath.sqrt(x0 * x1)
            elif x0 == 0:
                m = x1 / 2**20
            else:
                m = (x0 + x1) / 2
            fm = _mp_eval(a, m)
            if fm == 0:
                return +m
            if (fm > 0) == (f0 > 0):
                x0, f0 = m, fm
            else:
                x1 = m
        return (x0 + x1) / 2


@dataclass(frozen=True)
class Oracle:
    """Truth for one polynomial and window.

    root:  smallest real root in (0, tmax] (an mpf), or None.
    kind:  "simple"; "double" when root is a repeated root or another root
           (real or complex) lies within relative 1e-6 of it -- a touch that
           rounding split; "none".
    touches: real parts (mpf) of complex pairs with |Im| <= 1e-6 |z| lying in
           (0, min(root, tmax)]: near-touches a grazing solver may report.
    kappa: relative condition number of root, sum|c_i| r^i / (|p'(r)| r)
           (inf for a repeated root).  A backward-stable evaluation with
           error gamma_k sum|c_i| r^i puts the root within ~ gamma_k kappa.
    """

    root: mpmath.mpf | None
    kind: str
    touches: tuple[mpmath.mpf, ...]
    kappa: float


NEAR = mpmath.mpf("1e-6")


def _in_window(x: mpmath.mpf, tmax: float) -> bool:
    """x <= tmax, allowing for the last digits of a 60-digit root that is
    exactly tmax (polyroots may land a hair above it)."""
    return math.isinf(tmax) or x <= tmax * (1 + mpmath.mpf("1e-45"))


def _polyroots(mp_coeffs: list[mpmath.mpf]) -> list[mpmath.mpc]:
    """mpmath's Durand-Kerner needs extra working precision when the
    coefficients span hundreds of decades (TOMS case 22); escalate."""
    for extraprec in (400, 1200, 3000):
        try:
            return mpmath.polyroots(mp_coeffs, maxsteps=800, extraprec=extraprec)
        except mpmath.libmp.libhyper.NoConvergence:
            continue
    raise AssertionError("oracle: polyroots did not converge")


@lru_cache(maxsize=None)
def oracle(coeffs: tuple[float, ...], tmax: float = math.inf) -> Oracle:
    """Smallest real root in (0, tmax] of the exact polynomial whose
    coefficients are the given doubles, at 60 digits.

    Leading exact zeros are dropped and factors of t divided out (the
    runtimes' contract: the next root strictly after 0).  The polynomial is
    split into square-free factors (Yun, exact rationals) so that mpmath's
    polyroots sees only simple roots and multiplicities are exact; the count
    of real roots in (0, tmax] is checked against a Sturm sequence so a
    misclassified root cannot go unnoticed: the first real root is proved
    by Sturm counts (exact) and, when mpmath's estimate fails that proof
    (polyroots works to absolute accuracy, so a root at 1e-300 comes back
    as 0), isolated by exact bisection and refined in mpmath."""
    p = _trim([Fraction(x) for x in coeffs])
    while len(p) > 1 and p[0] == 0:
        p = p[1:]
    if len(p) <= 1:
        return Oracle(None, "none", (), math.inf)
    hi = None if math.isinf(tmax) else Fraction(tmax)
    with mpmath.workdps(60):
        roots: list[mpmath.mpc] = []
        root, mult = None, 0
        for m, a in enumerate(_yun(p), start=1):
            if len(a) <= 1:
                continue
            mp_coeffs = [mpmath.mpf(x.numerator) / x.denominator for x in reversed(a)]
            rs = [mpmath.mpc(r) for r in _polyroots(mp_coeffs)]
            roots.extend(rs)
            hint = [mpmath.re(r) for r in rs if mpmath.im(r) == 0]
            r = _first_real_root(a, hint, hi)
            if r is not None and (root is None or r < root):
                root, mult = r, m
        limit = root if root is not None else (mpmath.inf if hi is None else mpmath.mpf(tmax))
        touches = tuple(sorted(
            mpmath.re(z) for z in roots
            if mpmath.im(z) > 0 and abs(mpmath.im(z)) <= NEAR * abs(z) and 0 < mpmath.re(z) <= limit
        ))
        if root is None:
            return Oracle(None, "none", touches, math.inf)
        near = [z for z in roots if abs(z - root) <= NEAR * root]
        kind = "double" if mult > 1 or len(near) > 1 else "simple"
        kappa = math.inf
        if kind == "simple":
            pc = [mpmath.mpf(x) for x in coeffs]
            num = sum(abs(ci) * root**i for i, ci in enumerate(pc))
            dp = sum(i * ci * root ** (i - 1) for i, ci in enumerate(pc) if i)
            kappa = float(num / (abs(dp) * root)) if dp != 0 else math.inf
        return Oracle(root, kind, touches, kappa)


def rel_error(t: float, exact: mpmath.mpf) -> float:
    """|t - exact| / |exact| at high precision."""
    with mpmath.workdps(60):
        return float(abs(mpmath.mpf(t) - exact) / abs(exact))


# ---------------------------------------------------------------------------
# Orellana & De Michele, ACM TOMS 46(2) 2020, Algorithm 1010, table of 24
# ---------------------------------------------------------------------------
# Roots as in the paper's accuracy test (cases 1-22), multiplied out exactly
# and rounded to double; cases 23 and 24 are given by coefficients.  For the
# first-positive-root problem many cases have no positive root, so each case
# also appears mirrored (t -> -t), which makes the negative roots the ones
# that matter.  Values taken from the published test program of the paper's
# authors (cridemichel/quarticpp accuracytest.cpp), not from the PDF table.

R = str  # exact decimal root
TOMS_ROOTS: dict[int, tuple[tuple[R, ...], tuple[tuple[R, R], ...]]] = {
    1: (("1E9", "1E6", "1E3", "1"), ()),
    2: (("2.003", "2.002", "2.001", "2"), ()),
    3: (("1E53", "1E50", "1E49", "1E47"), ()),
    4: (("1E14", "2", "1", "-1"), ()),
    5: (("-2E7", "1E7", "1", "-1"), ()),
    6: (("1E7", "-1E6"), (("1", "1"),)),
    7: (("-7", "-4"), (("-1E6", "1E5"),)),
    8: (("1E8", "11"), (("1E3", "1"),)),
    9: ((), (("1E7", "1E6"), ("1", "2"))),
    10: ((), (("1E4", "3"), ("-7", "1E3"))),
    11: ((), (("1.001", "4.998"), ("1.000", "5.001"))),
    12: ((), (("1E3", "3"), ("1E3", "1"))),
    13: ((), (("2", "1E4"), ("1", "1E3"))),
    14: (("1000", "1000", "1000", "1000"), ()),
    15: (("1000", "1000", "1000", str(Fraction(1, 2**48))), ()),
    16: ((), (("1E16", "1E7"), ("1", "0.1"))),
    17: (("10000", "10001", "10010", "10100"), ()),
    18: ((), (("4E5", "3E2"), ("3E4", "7E3"))),
    19: (("1E44", "1E30", "1E30", "1"), ()),
    20: (("1E14", "1E7", "1E7", "1"), ()),
    21: (("1E15", "1E7", "1E7", "1"), ()),
    22: (("1E154", "1E152", "10", "1"), ()),
}


def _toms_coeffs(k: int) -> tuple[float, ...]:
    if k == 23:
        return (0.001, 0.375, 1.0, 1.0, 1.0)
    if k == 24:
        s = Fraction(10) ** 30
        exact = (-s, s * s + s, 1 / s - s * s, -(1 + 1 / s), Fraction(1))
        return tuple(float(x) for x in exact)
    real, pairs = TOMS_ROOTS[k]
    return poly_from_roots([Fraction(r) for r in real], [(Fraction(a), Fraction(b)) for a, b in pairs])


# Per-case relative-error bounds for the quartics.  Interval methods: 4 ulp-
# units (4u) where the root is well conditioned (kappa ~ 1..10); the closed
# quartic 8u.  The two exceptions are condition-limited, not solver-limited:
# toms2 (cluster 2.000..2.003) and toms17 (10000..10100) have kappa ~ 2e10 in
# the *double* coefficients, so n u kappa ~ 1e-5 is what any backward-stable
# method can promise; the first interval solver measured ~5e-8 and ~3e-7,
# the Budan-Fourier one (final step in compensated Horner) ~5e-17.
# GSL (companion matrix, backward stable for the matrix, not for the
# coefficients) gets its own measured bound (about 5x the measurement,
# rounded up to a decade); where it cannot meet any useful bound the method
# is left out: toms15 (root 2^-48 next to a triple root at 1000), toms19
# (roots 1 and 1e30/1e44), toms24 (root 1e-30 next to +-1e30) -- roots far
# below the largest one come back with absolute, not relative, accuracy --
# and toms14 (quadruple root at 1000, exact coefficients: GSL reports it
# as complex pairs with relative imaginary parts above sqrt(eps)).
_Q = {"interval": 4 * U, "interval-nograze": 4 * U, "closed": 8 * U}
_TOMS_BOUNDS: dict[str, dict[str, float]] = {
    "toms1": {**_Q, "gsl": 4 * U},
    "toms2": {"interval": 2e-7, "interval-nograze": 2e-7, "closed": 1e-6, "gsl": 1e-6},
    "toms3": {**_Q, "gsl": 1e-13},
    "toms4": {**_Q, "gsl": 1e-10},
    "toms4-mirror": {**_Q, "gsl": 1e-10},
    "toms5": {**_Q, "gsl": 1e-14},
    "toms5-mirror": {**_Q, "gsl": 1e-14},
    "toms6": {**_Q, "gsl": 1e-14},
    "toms6-mirror": {**_Q, "gsl": 1e-14},
    "toms7-mirror": {**_Q, "gsl": 1e-12},
    "toms8": {**_Q, "gsl": 1e-12},
    # a quadruple root, exact coefficients: the interval method answers the left edge of
    # compensated Horner's band around it (never later than the exact first root, whatever
    # rounding did to the coefficients: issue 33, item 11), 7.1e-8 relative early, a touch
    "toms14": {"interval": 1e-7, "closed": 8 * U},
    "toms15": dict(_Q),
    "toms17": {"interval": 1e-6, "interval-nograze": 1e-6, "closed": 1e-6, "gsl": 1e-4},
    "toms19": dict(_Q),
    "toms20": {**_Q, "gsl": 1e-10},
    "toms21": {**_Q, "gsl": 1e-10},
    "toms22": {**_Q, "gsl": 1e-14},
    "toms23-mirror": {**_Q, "gsl": 1e-13},
    "toms24": dict(_Q),
    "toms24-mirror": {**_Q, "gsl": 4 * U},
}


def toms_cases() -> list[Case]:
    """The 24 quartics, each as given and mirrored.  The expectation (root /
    none / graze) comes from the oracle; bounds from the tables above."""
    out = []
    for k in range(1, 25):
        c = _toms_coeffs(k)
        for name, cc in ((f"toms{k}", c), (f"toms{k}-mirror", mirror(c))):
            o = oracle(cc)
            expect = {"simple": "root", "double": "graze", "none": "none"}[o.kind]
            bounds = _TOMS_BOUNDS.get(name, {})
            out.append(Case(name, "toms1010", cc, math.inf, expect, bounds))
    return out


# ---------------------------------------------------------------------------
# The other families
# ---------------------------------------------------------------------------

KAHAN = (94906268.375, -2 * 94906267.375, 94906266.375)
"""Kahan's quadratic a t^2 - 2 b t + c with a=94906266.375, b=94906267.375,
c=94906268.375: roots 1 and 1 + 2/a = 1.0000000210734243...; the naive
discriminant b*b - a*c is 0 in double (exact: 1)."""


def named_cases() -> list[Case]:
    """Hand-made families: quadratic, grazing octics, roots near 0, degree
    drop, clusters, scales, windows, invalid input."""
    # Well-conditioned roots: a few units of roundoff for our methods; GSL
    # gets 1e-13 where it can meet it (see the families below for where not).
    tight = {"interval": 4 * U, "interval-nograze": 4 * U, "closed": 8 * U, "gsl": 1e-13}
    ours = {k: v for k, v in tight.items() if k != "gsl"}
    cases = [
        Case("kahan", "quadratic", KAHAN, bounds={m: 2 * U for m in METHODS}),
        Case("kahan-mirror", "quadratic", mirror(tuple(-x for x in KAHAN)), expect="none"),
        Case("quad-simple", "quadratic", poly_from_roots(["0.5", "3"]), bounds={m: 2 * U for m in METHODS}),
        Case("quad-complex", "quadratic", poly_from_roots([], [("1", "1")]), expect="none"),
        Case("quad-double", "quadratic", (4.0, -4.0, 1.0), expect="graze", bounds={m: 2 * U for m in METHODS}),
        Case("linear", "quadratic", (-3.0, 2.0), bounds={m: 2 * U for m in METHODS}),
    ]
    # Grazing: degree 8 with a double first root, then later simple roots.
    # Without a graze check the solver would skip to the later root.
    # A double root is determined only to ~sqrt(u) by double coefficients.
    # GSL: 1e-6 where it reports the double root at all (graze8-int, -big);
    # it misses graze8-half/-small/-third (complex pair above sqrt(eps)
    # relative imaginary part, so it goes on to a later root): not asserted.
    graze_bounds = {"interval": 1e-7, "closed": 1e-7}
    gsl_graze = {"graze8-int": 1e-6, "graze8-big": 1e-6}
    for name, dbl, rest, pairs in (
        ("graze8-int", "2", ["5", "7", "-1", "-3", "9", "11"], []),
        ("graze8-half", "0.5", ["3", "-2", "4"], [("-1", "2")]),
        ("graze8-small", "1E-3", ["1", "2", "-5"], [("3", "1")]),
        ("graze8-big", "1E3", ["3E3", "-1", "-2", "5E3", "-7"], []),
        ("graze8-third", Fraction(1, 3), ["1", "-1"], [("0.2", "1"), ("-2", "0.5")]),
    ):
        c = poly_from_roots([dbl, dbl, *rest], pairs)
        b = {**graze_bounds, **({"gsl": gsl_graze[name]} if name in gsl_graze else {})}
        cases.append(Case(name, "graze", c, expect="graze", bounds=b,
                          note="double root first; later simple roots in the window"))
    # A quartic touch whose coefficients are exact: p = (t-1)^2 (t^2+1) + 0.
    cases.append(Case("graze4-exact", "graze", poly_from_roots(["1", "1"], [("0", "1")]),
                      expect="graze", bounds={"interval": 1e-7, "closed": 1e-7, "gsl": 1e-6}))
    # Near-touch: minimum 1e-3 above zero: not a graze, no root.
    c = list(poly_from_roots(["2", "2", "-1", "-3"]))
    c[0] += 1e-3 * 3  # (t-2)^2 (t+1)(t+3) + 3e-3: min ~ 3e-3 > noise
    cases.append(Case("near-touch", "graze", tuple(c), expect="none"))

    # Roots near 0: relative, not absolute, accuracy.  GSL is not asserted:
    # the companion matrix gives accuracy relative to the largest root, so
    # 1e-12 next to roots ~5 comes back with relative error up to 4e-4 and
    # 1e-300 not at all.
    for r0 in ("1E-7", "1E-12", "1E-300"):
        for deg_rest in (["1", "2", "-3"], ["0.5", "2", "-3", "4", "-5", "6", "7"]):
            c = poly_from_roots([r0, *deg_rest])
            cases.append(Case(f"near0-{r0}-deg{len(deg_rest)+1}", "near-zero", c, bounds=ours))
    # Touching now (c0 == 0): the next root, not 0.
    cases.append(Case("touch-now", "near-zero", poly_from_roots(["0", "1", "2"]), bounds=tight))
    cases.append(Case("touch-now-twice", "near-zero", poly_from_roots(["0", "0", "0.25", "-1"]), bounds=tight))

    # Degree drop: exact zero leading terms, and a leading term 1e-30 relative.
    base = poly_from_roots(["0.75", "-2"], lead=3)
    cases.append(Case("drop-zero", "degree-drop", base + (0.0, 0.0), bounds=tight))
    cases.append(Case("drop-1e-30", "degree-drop", base + (3e-30,), bounds=tight,
                      note="cubic term 1e-30 relative; its extra root is near -1e30"))
    # (with tmax = inf the octic term is weighed over (0, K], K ~ 2.4e6 the bound on the
    # positive roots, and kept: its four complex roots of modulus ~5.6e7 stay, and GSL's
    # companion matrix, the original tool's method kept as the baseline, gives 0.5 to 1.3e-9)
    cases.append(Case("drop-1e-30-oct", "degree-drop", poly_from_roots(["0.5", "1", "-2", "3"]) + (0.0, 0.0, 0.0, 1e-30),
                      bounds={**tight, "gsl": 1e-8}))
    cases.append(Case("drop-window", "degree-drop", (1.0, -1.0, 1e-6), tmax=1e-9, expect="none",
                      note="quadratic term negligible over (0, 1e-9]; root 1 outside"))

    # Clustered roots.
    # Condition-limited (kappa 6e8 and 2e11 in the double coefficients:
    # n u kappa ~ 3e-7 and 2e-4); the first interval solver measured 7e-9 and
    # 1.3e-6, the Budan-Fourier one (compensated last step) ~1e-16.  GSL meets 1e-6
    # on the first and picks a wrong root on the octic (not asserted).
    cases.append(Case("cluster-1e-4", "cluster", poly_from_roots(["1", "1.0001", "1.0002", "5"]),
                      bounds={"interval": 4e-8, "interval-nograze": 4e-8, "closed": 4e-8, "gsl": 1e-6}))
    cases.append(Case("cluster-oct", "cluster",
                      poly_from_roots(["3", "3.001", "3.002", "3.003", "-1", "8"], [("1", "2")]),
                      bounds={"interval": 1e-5, "interval-nograze": 1e-5, "closed": 1e-5}))

    # Scales 1e-8 .. 1e8: the same shape, roots s, 2s, 4.5s, -s; pairs.
    for e in range(-8, 9, 4):
        s = Fraction(10) ** e
        c = poly_from_roots([s, 2 * s, Fraction(9, 2) * s, -s], [(s, s)], lead=Fraction(10) ** (-e))
        cases.append(Case(f"scale-1e{e}", "scale", c, bounds=tight))
        cases.append(Case(f"scale-1e{e}-window", "scale", c, tmax=float(Fraction(3, 2) * s), bounds=tight))

    # Windows.
    c = poly_from_roots(["1", "2", "3"])
    cases.append(Case("window-at-root", "window", c, tmax=1.0, bounds=tight, note="(0, tmax] is closed at tmax"))
    cases.append(Case("window-before", "window", c, tmax=0.999, expect="none"))
    cases.append(Case("all-negative", "window", poly_from_roots(["-1", "-2", "-3", "-4", "-5"]), expect="none"))
    cases.append(Case("all-complex", "window", poly_from_roots([], [("1", "1"), ("2", "0.5"), ("-1", "3")]), expect="none"))
    cases.append(Case("beyond-tmax", "window", poly_from_roots(["5", "6", "-1"]), tmax=4.0, expect="none"))
    cases.append(Case("constant", "window", (3.0,), expect="none"))
    cases.append(Case("zero-poly", "window", (0.0, 0.0, 0.0), expect="none"))
    cases.append(Case("huge-coeffs", "window", tuple(x * 2.0**900 for x in poly_from_roots(["0.5", "2", "-3"])),
                      bounds=tight))
    cases.append(Case("tiny-coeffs", "window", tuple(x * 2.0**-1000 for x in poly_from_roots(["0.5", "2", "-3"])),
                      bounds=tight))
    cases.append(Case("denormal-coeffs", "window", (-5e-324, 5e-324, 0.0), bounds=tight))

    # Invalid input.
    ok = poly_from_roots(["1", "2"])
    for name, c, tmax in (
        ("nan-coeff", (1.0, math.nan, 1.0), math.inf),
        ("inf-coeff", (1.0, -2.0, math.inf), math.inf),
        ("neg-inf-coeff", (-math.inf, 1.0), math.inf),
        ("nan-tmax", ok, math.nan),
        ("zero-tmax", ok, 0.0),
        ("neg-tmax", ok, -1.0),
        ("neg-inf-tmax", ok, -math.inf),
        ("degree-17", (1.0,) * 18, math.inf),
    ):
        cases.append(Case(name, "invalid", c, tmax, expect="invalid"))
    return cases


def all_cases() -> list[Case]:
    return toms_cases() + named_cases()


# ---------------------------------------------------------------------------
# Random polynomials
# ---------------------------------------------------------------------------


@dataclass(frozen=True)
class RandomCase:
    coeffs: tuple[float, ...]
    tmax: float


def random_cases(count: int, seed: int = 20240501) -> list[RandomCase]:
    """Deterministic random polynomials of degree 2..8 from random real roots
    (inside the window, negative, beyond tmax) and complex pairs, magnitudes
    log-uniform over 1e-3..1e3, random leading coefficient and sign; tmax is
    +inf or log-uniform over 1e-2..1e2, kept away from every real root."""
    rng = random.Random(seed)
    out = []
    while len(out) < count:
        deg = rng.randint(2, 8)
        npairs = rng.randint(0, deg // 2)
        nreal = deg - 2 * npairs
        mag = lambda: 10 ** rng.uniform(-3, 3)  # noqa: E731
        reals = [mag() * (1 if rng.random() < 0.6 else -1) for _ in range(nreal)]
        pairs = []
        for _ in range(npairs):
            r = mag()
            ang = rng.uniform(0.02, math.pi - 0.02)
            pairs.append((r * math.cos(ang), r * math.sin(ang)))
        tmax = math.inf if rng.random() < 0.4 else 10 ** rng.uniform(-2, 2)
        if any(abs(x - tmax) <= 1e-6 * tmax for x in reals):
            continue
        lead = 10 ** rng.uniform(-3, 3) * rng.choice((1, -1))
        out.append(RandomCase(poly_from_roots(reals, pairs, lead=lead), tmax))
    return out


# ---------------------------------------------------------------------------
# Judging a runtime's answer
# ---------------------------------------------------------------------------

GRAZING = ("interval", "closed", "gsl")  # methods that look for touches


def _near_any(t: float, points: Sequence[mpmath.mpf], rel: float) -> bool:
    return any(rel_error(t, x) <= rel for x in points)


def judge(case: Case, method: str, status: int, t: float, graze: bool) -> str | None:
    """None if (status, t, graze) from `method` meets the case, else why not.

    Always: status -1 exactly for invalid input, else 0/1 with t in the
    window.  A method without a bound for the case is held to no more.  A
    grazing method may stop at an oracle "touch" (a complex pair within 1e-6
    relative of the real axis before the first root): within rounding that
    is a double root.  (The interval method's graze *flag* is tested
    separately.)"""
    if case.expect == "invalid":
        return None if status == -1 else f"expected -1, got {status}"
    if status not in (0, 1):
        return f"status {status} on valid input"
    o = oracle(case.coeffs, case.tmax)
    if status == 1:
        if not (t > 0 and t <= case.tmax and math.isfinite(t)):
            return f"t={t!r} outside (0, {case.tmax}]"
        if method in GRAZING and o.touches and _near_any(t, o.touches, 1e-6):
            return None
    if case.expect == "none":
        return None if status == 0 else f"expected no root, got t={t!r} graze={graze}"
    bound = case.bounds.get(method)
    if bound is None:
        return None
    target = o.root
    if case.expect == "graze" and o.touches:
        target = o.touches[0]
    if status != 1:
        return f"missed the root {float(target)!r}"
    err = rel_error(t, target)
    if err > bound:
        return f"t={t!r} vs {float(target)!r}: rel err {err:.3g} > {bound:.3g}"
    return None


# ---------------------------------------------------------------------------
# Measuring
# ---------------------------------------------------------------------------


def worst_errors(results: Mapping[tuple[str, str], tuple[int, float, bool]]) -> dict[tuple[str, str], float]:
    """Worst relative error of the first root per (family, method) over the
    cases with a root (or a graze) that the method reported; a missed root
    counts as inf.  results maps (case name, method) -> (status, t, graze)."""
    by_name = {c.name: c for c in all_cases()}
    worst: dict[tuple[str, str], float] = {}
    for (name, method), (st, t, _g) in results.items():
        case = by_name[name]
        if case.expect not in ("root", "graze"):
            continue
        o = oracle(case.coeffs, case.tmax)
        target = o.touches[0] if case.expect == "graze" and o.touches else o.root
        err = rel_error(t, target) if st == 1 else math.inf
        if st == 1 and o.touches and _near_any(t, o.touches, 1e-6):
            err = min(err, min(rel_error(t, x) for x in o.touches))
        key = (case.family, method)
        worst[key] = max(worst.get(key, 0.0), err)
    return worst


def format_worst(worst: Mapping[tuple[str, str], float], title: str) -> str:
    methods = sorted({m for _, m in worst}, key=lambda m: METHODS.index(m))
    families = sorted({f for f, _ in worst})
    lines = [title, f"{'family':12s} " + " ".join(f"{m:>17s}" for m in methods)]
    for f in families:
        lines.append(f"{f:12s} " + " ".join(f"{worst.get((f, m), math.nan):17.2e}" for m in methods))
    return "\n".join(lines)


# Random polynomials: a simple first root must come back within k u max(1, n kappa), with k
# per method (the closed forms above degree 4 fall back to the interval solver).
# Bounds relative to the root's condition number kappa (see cases.Oracle):
# a backward-stable evaluation (error gamma_n sum|c_i| r^i) places the root
# within about n u kappa.  The constant covers Newton stopping at an ulp.
# Measured worst (3000 cases, seed in cases.random_cases): 2.4 for ours.
# GSL's error follows the scale of the largest root rather than kappa
# (measured worst 1.3e4, i.e. 1.3e-10 relative), hence its own constant.
RANDOM_BOUND = {"interval": 8.0, "interval-nograze": 8.0, "closed": 64.0, "gsl": 1e5}


def random_bound(method: str, degree: int, kappa: float) -> float:
    k = RANDOM_BOUND["interval"] if method == "closed" and degree > 4 else RANDOM_BOUND[method]
    return k * U * max(1.0, degree * kappa)


def random_failures(results: Iterable[tuple[RandomCase, str, tuple[int, float, bool]]]) -> Iterator[str]:
    """What went wrong on random polynomials, given (case, method, (status, t, graze)) results.
    Near-double first roots are skipped: the graze and cluster families test those."""
    for case, method, (st, t, _) in results:
        o = oracle(case.coeffs, case.tmax)
        if st not in (0, 1):
            yield f"{case}: [{method}] status {st}"
            continue
        if o.kind != "simple" or o.touches:
            continue
        bound = random_bound(method, len(case.coeffs) - 1, o.kappa)
        if o.root is None:
            if st != 0:
                yield f"{case}: [{method}] spurious root {t!r}"
        elif st != 1:
            yield f"{case}: [{method}] missed {float(o.root)!r}"
        elif rel_error(t, o.root) > bound:
            yield f"{case}: [{method}] rel err {rel_error(t, o.root):.3g} > {bound:.3g}"
