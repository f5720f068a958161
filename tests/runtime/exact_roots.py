"""An exact first-root oracle for coefficients of any magnitude (issue 12, "honest at the extremes").

The mpmath/Sturm oracle of ``cases.py`` is the reference for ordinary polynomials, but on the
fuzz vectors (coefficients of 1e-300 beside 1e300, subnormals, degree 16) its Sturm sequences
over rationals grow to millions of digits and one vector can take minutes.  This oracle works
on the same exact polynomial (the double coefficients, as rationals) with integer arithmetic
only, and is independent of both the runtimes and mpmath:

* the coefficients are scaled to integers (they are dyadic rationals);
* the smallest positive root is isolated by Descartes' rule of signs (the Collins-Akritas
  bisection: the sign variations of ``(1+y)^n p((a + b y)/(1+y))`` bound the number of roots
  in (a, b) and have its parity), first over dyadic exponent ranges (roots from 2^-2200 to
  2^2200: Cauchy's bounds for doubles), then by halving;
* a simple root is refined by exact bisection on the sign of p to 2^-80 relative (geometric
  while the bracket spans more than a factor 4);
* a cluster that Descartes cannot split at 2^-60 relative width (a double root, or roots
  closer than that) is reported as such (``kind == "cluster"``), and so is an exact multiple
  root met at a split point (width 0).

Everything is integer arithmetic on dyadic intervals (Fractions only at the interface): about
10 ms per fuzz vector, where the first version (rational Taylor shifts, arithmetic bisection
from 2^-2200) took 0.3 s and up to 9 s.

``first_root(coeffs, tmax)`` returns what is true; ``judge(coeffs, tmax, status, t, graze,
eps)`` says whether a runtime's answer agrees, allowing exactly what the runtimes document: the
root to within ``max(2^-40, 64 n u kappa)`` relative (kappa its condition number), a reported
touch where ``|p|`` is within ``2^-40`` of ``sum |c_i| t^i`` plus the contact skin eps
(rounding noise; a cluster counts too), status 0 when the first root is not representable
(below the smallest subnormal or above DBL_MAX), is within its tolerance of tmax or so
ill-conditioned that the tolerance exceeds 1 (a sign change inside the rounding noise, as in a
rounded (t - a)^12), or is a cluster of even multiplicity (a touch the rounding of the
coefficients may have removed; an odd one is a sign change: a miss), an absolute 2^-1074 on a
subnormal root, and the header's rule that drops a negligible leading term (step 3; written
here from the header, in exact logarithms: ``documented_reduction``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from fractions import Fraction
from typing import Sequence

U = 2.0**-53
# Cauchy's bounds for double coefficients: every nonzero root has 2^-2099 <= |t| <= 1 + 2^2098
# (|c_i / c_n| < 2^1024 / 2^-1074), so (2^LOW_EXP, 2^HIGH_EXP) holds every positive root
LOW_EXP = -2200
HIGH_EXP = 2200
REFINE_BITS = 80
CLUSTER_BITS = 60
ROOT_REL = 2.0**-40   # the floor of the root tolerance (relative)
TOUCH_REL = 2.0**-40  # |p(t)| <= this times sum |c_i| t^i: a touch within rounding noise
DBL_MAX = 1.7976931348623157e308
TRUE_MIN = 5e-324


@dataclass(frozen=True)
class Truth:
    """The smallest positive root of the exact polynomial in (0, tmax].

    kind: "none", "simple" (lo <= root <= hi, hi - lo <= 2^-80 hi) or "cluster" (two or more
    roots, counted with multiplicity, in [lo, hi], hi - lo <= 2^-60 hi: a double root or a
    touch within rounding); kappa: the condition number sum |c_i| r^i / (|p'(r)| r) of a
    simple root (inf for a cluster)."""

    kind: str
    lo: Fraction = Fraction(0)
    hi: Fraction = Fraction(0)
    kappa: float = math.inf


def _int_poly(coeffs: Sequence[float]) -> list[int]:
    """The coefficients times a power of two that makes them all integers (same roots)."""
    fr = [Fraction(x) for x in coeffs]
    shift = max(f.denominator.bit_length() - 1 for f in fr)
    return [int(f * (1 << shift)) for f in fr]


def _variations(v: Sequence[int]) -> int:
    count, last = 0, 0
    for x in v:
        if x:
            s = 1 if x > 0 else -1
            count += s * last < 0
            last = s
    return count


def _taylor_shift1(p: list[int]) -> list[int]:
    """p(x + 1), exact (p low first)."""
    q = list(p)
    n = len(q) - 1
    for i in range(n):
        for j in range(n - 1, i - 1, -1):
            q[j] += q[j + 1]
    return q


def _descartes01(p: list[int]) -> int:
    """Sign variations of (1+y)^n p(1/(1+y)): a bound on the roots in (0, 1), with its parity."""
    return _variations(_taylor_shift1(p[::-1]))


def _on_interval(p: list[int], a: Fraction, b: Fraction) -> list[int]:
    """An integer multiple of p(a + (b - a) z), as a polynomial in z (exact, integers only:
    with D the common denominator, D^n p((A + W z) / D) is the homogenised p shifted by A,
    its coefficient i times W^i; common factors of two are divided out)."""
    den = a.denominator * b.denominator // math.gcd(a.denominator, b.denominator)
    A = a.numerator * (den // a.denominator)
    W = b.numerator * (den // b.denominator) - A
    n = len(p) - 1
    q = [c * den ** (n - i) for i, c in enumerate(p)]
    for i in range(n):  # Taylor shift by A
        for j in range(n - 1, i - 1, -1):
            q[j] += A * q[j + 1]
    wi = 1
    for i in range(n + 1):
        q[i] *= wi
        wi *= W
    return _drop_twos(q)


def _drop_twos(q: list[int]) -> list[int]:
    """q divided by the largest power of two that divides every coefficient (same roots)."""
    tz = min(((c & -c).bit_length() - 1 for c in q if c), default=0)
    return [c >> tz for c in q] if tz else q


def _eval_sign(p: list[int], x: Fraction) -> int:
    """Sign of p(x), exact: homogeneous Horner, sum p_i num^i den^(n - i)."""
    num, den = x.numerator, x.denominator
    acc, dpow = p[-1], 1
    for c in reversed(p[:-1]):
        dpow *= den
        acc = acc * num + c * dpow
    return (acc > 0) - (acc < 0)


def _halves(q: list[int]) -> tuple[list[int], list[int]]:
    """q on (0, 1/2) and (1/2, 1), each rescaled to (0, 1) (integer multiples)."""
    n = len(q) - 1
    left = [c << (n - i) for i, c in enumerate(q)]  # 2^n q(z / 2)
    return left, _taylor_shift1(left)


def _geometric_mid(lo: Fraction, hi: Fraction) -> Fraction | None:
    """A power of two between lo and hi when they are more than a factor 4 apart, else None."""
    if hi <= 4 * lo:
        return None
    e_lo = lo.numerator.bit_length() - lo.denominator.bit_length()
    e_hi = hi.numerator.bit_length() - hi.denominator.bit_length()
    m = Fraction(2) ** ((e_lo + e_hi) // 2)
    return m if lo < m < hi else None


def _first_in(p: list[int], a: Fraction, b: Fraction) -> tuple[str, Fraction, Fraction] | None:
    """Smallest root of p in (a, b) (0 < a < b): None, or ("simple", lo, hi) with one simple
    root in (lo, hi) (or lo == hi, an exact root), or ("cluster", lo, hi).  Intervals that
    span more than a factor 4 are split at a power of two between them (roots of any
    magnitude), the others halved (Collins-Akritas, integer Taylor shifts only)."""
    stack: list[tuple[Fraction, Fraction, list[int] | None]] = [(a, b, None)]
    while stack:
        lo, hi, q = stack.pop()
        if q is None:
            q = _on_interval(p, lo, hi)
        v = _descartes01(q)
        if v == 0:
            continue
        if v == 1:
            return "simple", lo, hi
        if hi - lo <= hi * Fraction(1, 2**CLUSTER_BITS):
            return "cluster", lo, hi
        mid = _geometric_mid(lo, hi)
        halves: tuple[list[int] | None, list[int] | None] = (None, None)
        if mid is None:
            mid = (lo + hi) / 2
            halves = _halves(q)
        if _eval_sign(p, mid) == 0:
            # a root at the split point: the first root, unless the left part holds one
            found = _first_in(p, lo, mid)
            return found if found is not None else _exact_root(p, mid)
        stack.append((mid, hi, halves[1]))
        stack.append((lo, mid, halves[0]))
    return None


def _multiplicity(p: list[int], x: Fraction) -> int:
    """How many times x is a root of p (0: not a root), exact."""
    m = 0
    while len(p) > 1 and _eval_sign(p, x) == 0:
        m += 1
        p = [i * c for i, c in enumerate(p)][1:]
    return m


def _exact_root(p: list[int], x: Fraction) -> tuple[str, Fraction, Fraction]:
    """x, a root of p: simple, or a multiple root (a "cluster" of width 0)."""
    return ("simple" if _multiplicity(p, x) == 1 else "cluster"), x, x


def _crosses(p: list[int], lo: Fraction, hi: Fraction) -> bool:
    """Does p change sign across the cluster [lo, hi] (an odd number of roots)?"""
    if lo == hi:
        return _multiplicity(p, lo) % 2 == 1
    return _eval_sign(p, lo) != _eval_sign(p, hi)


def _refine(p: list[int], lo: Fraction, hi: Fraction) -> tuple[Fraction, Fraction]:
    """Bisection on the sign of p (one simple root in (lo, hi)) to 2^-REFINE_BITS relative:
    geometric (at powers of two) while the ends are more than a factor 4 apart."""
    if lo == hi:
        return lo, hi
    slo = _eval_sign(p, lo)
    while hi - lo > hi * Fraction(1, 2**REFINE_BITS):
        mid = _geometric_mid(lo, hi) or (lo + hi) / 2
        s = _eval_sign(p, mid)
        if s == 0:
            return mid, mid
        if s == slo:
            lo = mid
        else:
            hi = mid
    return lo, hi


def _kappa(coeffs: Sequence[float], r: Fraction) -> float:
    c = [Fraction(x) for x in coeffs]
    size = sum(abs(ci) * r**i for i, ci in enumerate(c))
    slope = abs(sum(i * ci * r ** (i - 1) for i, ci in enumerate(c) if i))
    if slope == 0:
        return math.inf
    return math.exp(min(_log(size) - _log(slope * r), 709.0))  # (inf-like beyond 1e308)


def _log(x: Fraction) -> float:
    """log of a positive rational of any size."""
    return math.log(x.numerator) - math.log(x.denominator)


def first_root(coeffs: Sequence[float], tmax: float) -> Truth:
    """The truth for finite coefficients and tmax > 0 (tmax may be inf)."""
    return _first_root(tuple(coeffs), tmax)


@lru_cache(maxsize=4096)  # judge() asks again for each method run on one vector
def _first_root(coeffs: tuple[float, ...], tmax: float) -> Truth:
    c = list(coeffs)
    while c and c[-1] == 0:
        c.pop()
    while c and c[0] == 0:  # the next root strictly after 0
        c.pop(0)
    if len(c) <= 1:
        return Truth("none")
    p = _int_poly(c)
    top = Fraction(tmax) if math.isfinite(tmax) else Fraction(2) ** HIGH_EXP
    low = Fraction(2) ** LOW_EXP
    if top <= low:
        return Truth("none")
    found = _first_in(p, low, top)
    if found is None:
        if _eval_sign(p, top) == 0:
            kind, lo, hi = _exact_root(p, top)
            return Truth(kind, lo, hi, _kappa(c, top) if kind == "simple" else math.inf)
        return Truth("none")
    kind, lo, hi = found
    if kind == "cluster":
        return Truth("cluster", lo, hi)
    lo, hi = _refine(p, lo, hi)
    return Truth("simple", lo, hi, _kappa(c, hi))


def _representable(x: Fraction) -> bool:
    return Fraction(TRUE_MIN) / 2 < x <= Fraction(DBL_MAX)


def _near_zero(coeffs: Sequence[float], t: float, rel: float, eps: float = 0.0) -> bool:
    """|p(t)| <= rel * sum |c_i| t^i + eps, exactly."""
    x = Fraction(t)
    c = [Fraction(v) for v in coeffs]
    val = sum(ci * x**i for i, ci in enumerate(c))
    size = sum(abs(ci) * x**i for i, ci in enumerate(c))
    return abs(val) <= Fraction(rel) * size + Fraction(eps)


def _peak(coeffs: Sequence[float], t: float) -> bool:
    """|p| strictly larger at t than at t (1 -+ 2^-16), exactly: t is a maximum of |p| -- the
    farthest pass nearby, which no skin makes a touch (the header: "reported at the time of
    closest approach").  A touch is reported within far less than 2^-16 of its critical point,
    so a minimum never reads as a peak."""
    x = Fraction(t)
    c = [Fraction(v) for v in coeffs]

    def size(y: Fraction) -> Fraction:
        return abs(sum(ci * y**i for i, ci in enumerate(c)))

    v, d = size(x), x / 2**16
    return size(x - d) < v and size(x + d) < v


def _log2(x: float) -> float:
    return math.log2(abs(x))


def _lead_negligible(c: list[float], T: float) -> bool:
    """The header's step 3, "a leading coefficient is dropped when it is negligible over the
    window [0, T]": |c_n| T^(n-i) <= 4 n eps |c_i| for some i < n.  Written from the header,
    not the code, in logarithms, and lenient by 1e-9 in the exponent."""
    n = len(c) - 1
    if not math.isfinite(T):
        return False
    lt = _log2(T)
    k = _log2(4 * n * 2.0**-52)
    return any(c[i] != 0 and _log2(c[n]) + (n - i) * lt <= k + _log2(c[i]) + 1e-9 for i in range(n))


def _root_bound(c: list[float], every_root: bool) -> float:
    """The header's bound, "2 max |c_i / c_n|^(1/(n-i)), each ratio rounded up to a power of two
    using exponents", over the c_i of the sign opposite to c_n's (Kioustelidis: the positive
    roots), or over every c_i with a contact skin; inf where none counts or it is beyond
    DBL_MAX (then nothing is weighed)."""
    n = len(c) - 1
    ratios = [math.ceil((math.frexp(c[i])[1] - math.frexp(c[n])[1] + 1) / (n - i))
              for i in range(n) if c[i] != 0 and (every_root or (c[i] < 0) != (c[n] < 0))]
    if not ratios:
        return math.inf
    b = max(ratios) + 1
    return math.ldexp(1.0, b) if b < 1024 else math.inf


def documented_window(coeffs: Sequence[float], tmax: float,
                      eps: float = 0.0) -> tuple[tuple[float, ...], float]:
    """The coefficients after the header's steps 1-3 (zero leading terms dropped, factors of t
    divided out, negligible leading terms dropped, until nothing changes), and the window's end
    they are solved over: with tmax = inf a leading term is weighed over (0, K], K the bound on
    the positive roots (every root with a skin eps > 0) of the polynomial as it stands, and
    once one is dropped the window is (0, K]."""
    c = list(coeffs)
    while True:
        while c and c[-1] == 0:
            c.pop()
        if len(c) <= 1:
            return tuple(c), tmax
        if c[0] == 0:
            c.pop(0)
            continue
        T = _root_bound(c, eps > 0) if math.isinf(tmax) else tmax
        if _lead_negligible(c, T):
            tmax = T
            c.pop()
        else:
            return tuple(c), tmax


def documented_reduction(coeffs: Sequence[float], tmax: float,
                         eps: float = 0.0) -> tuple[float, ...]:
    """The coefficients of documented_window()."""
    return documented_window(coeffs, tmax, eps)[0]


def judge(coeffs: Sequence[float], tmax: float, status: int, t: float, graze: bool,
          eps: float = 0.0) -> str:
    """judge_exact() of the coefficients, or of their documented_window(): where the header's
    rule drops a leading term (negligible over a window that holds every root to find), the
    rest's roots in that window count, within their own tolerance ("ok-lead-dropped").  eps:
    the contact skin the runtime was given (a touch may then be reported wherever |p| is within
    it)."""
    verdict = judge_exact(coeffs, tmax, status, t, graze, eps)
    if verdict.startswith("ok"):
        return verdict
    reduced, window = documented_window(coeffs, tmax, eps)
    trimmed = tuple(coeffs)
    while trimmed and trimmed[-1] == 0:
        trimmed = trimmed[:-1]
    if len(reduced) < len(trimmed) and judge_exact(reduced, window, status, t, graze, eps).startswith("ok"):
        return "ok-lead-dropped"
    return verdict


def judge_exact(coeffs: Sequence[float], tmax: float, status: int, t: float, graze: bool,
                eps: float = 0.0) -> str:
    """"ok-..." when the answer is right within what the runtimes document, else why not:
    "wrong-early" / "wrong-late" (a root reported before / after the first one), "false" (a
    root where there is none), "miss" (status 0 with a representable first root: simple, or
    a cluster of odd multiplicity, where p changes sign).  For a graze-checking method
    (the default): a method without the graze check may skip a touch."""
    truth = first_root(coeffs, tmax)
    n = len(coeffs) - 1
    if status == 0:
        if truth.kind == "none":
            return "ok-none"
        if not _representable(truth.hi):
            return "ok-not-representable"
        if truth.kind == "cluster":
            if _crosses(_int_poly(coeffs), truth.lo, truth.hi):
                return "miss"
            return "ok-cluster-missed"  # even: a touch rounding may have removed
        tol = _tolerance(n, truth.kappa)
        if tol >= 1:
            return "ok-ill-conditioned"  # not located within itself: a sign change in the noise
        if math.isfinite(tmax) and truth.lo >= Fraction(tmax) * (1 - Fraction(tol)):
            return "ok-at-tmax"  # within its error bound of tmax
        return "miss"
    x = Fraction(t)
    near = _near_zero(coeffs, t, TOUCH_REL, eps) and not _peak(coeffs, t)
    if truth.kind == "none":
        return "ok-touch" if near else "false"
    if truth.kind == "cluster":
        width = truth.hi * Fraction(1, 2**20)
        if truth.lo - width <= x <= truth.hi + width or (near and x < truth.lo):
            return "ok-cluster"
        return "wrong-early" if x < truth.lo else "wrong-late"
    if math.isinf(_tolerance(n, truth.kappa)):
        return "ok-root"  # kappa infinite: p'(r) = 0 exactly, any answer near it
    tol = Fraction(_tolerance(n, truth.kappa))
    slack = Fraction(TRUE_MIN)  # a subnormal root has fewer bits
    if truth.lo * (1 - tol) - slack <= x <= truth.hi * (1 + tol) + slack:
        return "ok-root"
    if near and x < truth.lo:
        return "ok-touch"
    return "wrong-early" if x < truth.lo else "wrong-late"


def _tolerance(n: int, kappa: float) -> float:
    """Relative error allowed for a simple root of condition number kappa (inf: any)."""
    tol = max(ROOT_REL, 64 * n * U * kappa)
    return tol if math.isfinite(tol) else math.inf
