"""Adversarial inputs for the root runtimes, as data (issue 12, "runtimes at the extremes").

``vectors(count, seed)`` is deterministic: the same seed gives the same vectors in every
run and every language test.  Each vector is ``(coeffs, tmax)`` with a degree of 0..16
(sometimes 17: invalid), coefficients drawn from pools that break naive code -- NaN, +-Inf,
+-0, subnormals, +-DBL_MAX and 1e+-308, mixtures of 1e-200 and 1e200, exact powers
``(t - a)^k`` (multiple roots), and ordinary polynomials with one extreme coefficient -- and
``tmax`` of 0, negative, NaN, infinite, tiny, huge or ordinary.

``check_answer`` states what every runtime must do with every vector, whatever its method:
status -1 exactly for invalid input, and status 1 only with a finite t in (0, tmax].
"""
from __future__ import annotations

import math
import random
import struct
from fractions import Fraction
from typing import Iterator

MAX_DEGREE = 16
DBL_MAX = 1.7976931348623157e308
DBL_MIN = 2.2250738585072014e-308
TRUE_MIN = 5e-324

Vector = tuple[tuple[float, ...], float]


def _subnormal(rng: random.Random) -> float:
    bits = rng.randrange(1, 1 << 52)
    return struct.unpack("<d", struct.pack("<Q", bits))[0] * rng.choice((1, -1))


def _special(rng: random.Random) -> float:
    return rng.choice((
        math.nan, math.inf, -math.inf, 0.0, -0.0, TRUE_MIN, -TRUE_MIN, DBL_MIN, -DBL_MIN,
        DBL_MAX, -DBL_MAX, 1e308, -1e308, 1e-308, -1e-308, 1.0, -1.0, 0.5, 2.22e-16,
        _subnormal(rng),
    ))


def _magnitude(rng: random.Random, lo: float = -300, hi: float = 300) -> float:
    return 10 ** rng.uniform(lo, hi) * rng.choice((1, -1))


def _finite_special(rng: random.Random) -> float:
    while True:
        x = _special(rng)
        if math.isfinite(x):
            return x


def _tmax(rng: random.Random) -> float:
    r = rng.random()
    if r < 0.35:
        return math.inf
    if r < 0.45:
        return rng.choice((0.0, -0.0, -1.0, math.nan, -math.inf, -TRUE_MIN))
    if r < 0.55:
        return rng.choice((TRUE_MIN, 1e-300, DBL_MIN, 1e-200, DBL_MAX, 1e300))
    return 10 ** rng.uniform(-12, 12)


def _power(rng: random.Random) -> tuple[float, ...]:
    """lead (t - a)^k times maybe (t - b), multiplied out exactly, rounded once."""
    a = Fraction(_magnitude(rng, -200, 200) if rng.random() < 0.3 else _magnitude(rng, -3, 3))
    k = rng.randint(2, MAX_DEGREE)
    c = [Fraction(1)]
    for _ in range(k):
        c = [(c[i - 1] if i > 0 else 0) - a * (c[i] if i < len(c) else 0) for i in range(len(c) + 1)]
    if k < MAX_DEGREE and rng.random() < 0.5:
        b = Fraction(_magnitude(rng, -3, 3))
        c = [(c[i - 1] if i > 0 else 0) - b * (c[i] if i < len(c) else 0) for i in range(len(c) + 1)]
    lead = Fraction(_magnitude(rng, -100, 100))
    out = []
    for x in c:
        v = x * lead
        try:
            out.append(float(v))
        except OverflowError:
            out.append(math.inf if v > 0 else -math.inf)
    return tuple(out)


def _one(rng: random.Random) -> Vector:
    kind = rng.random()
    deg = rng.randint(0, MAX_DEGREE + 1) if rng.random() < 0.03 else rng.randint(0, MAX_DEGREE)
    if kind < 0.2:  # anything from the special pool
        c = tuple(_special(rng) for _ in range(deg + 1))
    elif kind < 0.4:  # finite specials and subnormals: valid, nasty
        c = tuple(_finite_special(rng) for _ in range(deg + 1))
    elif kind < 0.55:  # mixed 1e-200 / 1e200
        c = tuple(rng.choice((1e-200, 1e200, 1e-100, 1e100)) * rng.choice((1, -1)) for _ in range(deg + 1))
    elif kind < 0.7:  # any magnitude
        c = tuple(_magnitude(rng) for _ in range(deg + 1))
    elif kind < 0.85:  # multiple roots
        c = _power(rng)
    else:  # ordinary, with one or two extreme coefficients
        c = [_magnitude(rng, -2, 2) for _ in range(deg + 1)]
        for _ in range(rng.randint(1, 2)):
            c[rng.randrange(deg + 1)] = _finite_special(rng) if rng.random() < 0.8 else _special(rng)
        c = tuple(c)
    return c, _tmax(rng)


def vectors(count: int, seed: int = 12) -> list[Vector]:
    rng = random.Random(seed)
    return [_one(rng) for _ in range(count)]


def is_invalid(c: tuple[float, ...], tmax: float) -> bool:
    return (not 1 <= len(c) <= MAX_DEGREE + 1 or math.isnan(tmax) or tmax <= 0
            or not all(math.isfinite(x) for x in c))


def check_answer(c: tuple[float, ...], tmax: float, status: int, t: float) -> str | None:
    """Why the answer breaks the contract, or None."""
    if is_invalid(c, tmax):
        return None if status == -1 else f"status {status} on invalid input"
    if status == -1:
        return "status -1 on valid input"
    if status == 1 and not (math.isfinite(t) and 0 < t <= tmax):
        return f"status 1 with t = {t!r} outside (0, {tmax!r}]"
    if status not in (0, 1):
        return f"status {status}"
    return None


def batches(count: int, size: int, seed: int = 12) -> Iterator[list[Vector]]:
    """count vectors in batches of at most size (for 10^6 on demand)."""
    for b in range(0, count, size):
        yield vectors(min(size, count - b), seed=seed * 1_000_003 + b)
