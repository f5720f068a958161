"""What every part of the solver shares: its constants and C's floating-point semantics
(``fma``, division, ``ldexp``)."""

from __future__ import annotations

import math
from fractions import Fraction


MAXN = 16
U = 2.0**-53
EPS = 2.0**-52
DBL_MIN = 2.0**-1022
TRUE_MIN = 2.0**-1074  # the least subnormal
DBL_MAX = 1.7976931348623157e308
SAFE_LOW = 2.0**120
SAFE_HIGH = 2.0**60
FAST_LIMIT_LOW = 2.0**100
FAST_LIMIT_HIGH = 2.0**56
MAX_ITER = 200
# after this many iterations a Newton step moving x by over 2^-10 of it in a bracket spanning
# more than a factor 8 becomes a geometric bisection (from lo = 0: hi / 2^64): far from every
# root Newton converges only linearly (see the C runtime)
SLOW_AFTER = 16
TOL_CRITICAL = 2.0**-36
TOL_LEVEL = 2.0**-28
PRECISE_FROM = 2.0**-26
GUESS_DONE = 2.0**-14  # C GUESS_DONE, GUESS_FAST: Laguerre also stops after a step below
GUESS_FAST = 2.0**-4  # GUESS_DONE (relative) at most GUESS_FAST of the step before
NOISE_STEP = 32 * U
MAX_SPLITS = 40
SPLIT_NEWTON = 2.0
MIN_WIDTH = 2.0**-20
EARLY_WIDTH = 0.25
MAX_SPREAD = 1021
INF = math.inf

Coeffs = list[float]


def fma_exact(a: float, b: float, c: float) -> float:
    if not (math.isfinite(a) and math.isfinite(b) and math.isfinite(c)):
        return a * b + c
    try:
        return float(Fraction(a) * Fraction(b) + Fraction(c))
    except OverflowError:
        return math.inf if Fraction(a) * Fraction(b) + Fraction(c) > 0 else -math.inf


fma = getattr(math, "fma", fma_exact)


def div(a: float, b: float) -> float:
    """a / b with IEEE semantics (C's), never ZeroDivisionError."""
    if b != 0:
        return a / b
    if a == 0 or math.isnan(a):
        return math.nan
    return math.copysign(math.inf, a) * math.copysign(1.0, b)


def ldexp(x: float, e: int) -> float:
    try:
        return math.ldexp(x, e)
    except OverflowError:
        return math.copysign(math.inf, x)


def ilogb(x: float) -> int:
    """2^e <= |x| < 2^(e+1), x finite and nonzero (subnormals included)."""
    return math.frexp(x)[1] - 1


def ceil_div(num: int, den: int) -> int:
    return -((-num) // den)
