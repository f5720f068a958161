"""The closed form for degree 2 (C: ``runtime/c/roots/quadratic.inc``)."""

from __future__ import annotations

import math
from typing import Sequence

from .shared import div, fma, ilogb, ldexp
from .evaluate import within_noise


def quad_roots(a: float, b: float, c: float) -> tuple[tuple[float, float] | None, float]:
    """Ascending real roots of a x^2 + b x + c (a != 0) and the discriminant's sign info."""
    m = max(abs(a), max(abs(b), abs(c)))
    e = ilogb(m)
    a, b, c = ldexp(a, -e), ldexp(b, -e), ldexp(c, -e)
    h = -0.5 * b
    p, q = h * h, a * c
    dp, dq = fma(h, h, -p), fma(a, c, -q)
    d = (p - q) + (dp - dq)
    if d < 0:
        return None, d
    w = h + math.copysign(math.sqrt(d), h)
    if w == 0:
        r1 = r2 = 0.0
    else:
        r1, r2 = div(w, a), div(c, w)
    return (min(r1, r2), max(r1, r2)), d


def first_root_quadratic(c: Sequence[float], tmax: float, skin: float,
                         lo: float = 0.0) -> tuple[float, bool] | None:
    roots, disc = quad_roots(c[2], c[1], c[0])
    if roots is not None:
        for r in roots:
            if lo < r <= tmax:
                return r, disc == 0
        return None
    if skin < 0:
        return None
    x = div(-c[1], 2 * c[2])
    if lo < x <= tmax and within_noise(c, 2, x, skin):
        return x, True
    return None
