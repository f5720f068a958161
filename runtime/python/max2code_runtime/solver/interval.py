"""The interval solver (C: ``runtime/c/roots/interval.inc``)."""

from __future__ import annotations

from typing import Sequence

from .shared import FAST_LIMIT_HIGH, FAST_LIMIT_LOW
from .isolate import CLEARED, isolate_first_root
from .derivative import derivative_method


def first_root_interval(p: Sequence[float], n: int, T: float, skin: float,
                        failed_w: float) -> tuple[float, bool, bool] | None:
    """First root in (0, T] of p (degree n >= 3, normalised, p[0] > 0: normalise's sign), as
    (t, graze, scanned): scanned where the derivative method found it (its scan's fma signs
    cannot see a crossing pair inside the noise: never_late looks again); failed_w: the window
    step 0b's test failed on, 0 if none (isolate_first_root)."""
    lo = 0.0
    if T <= (FAST_LIMIT_LOW if n <= 8 else FAST_LIMIT_HIGH):
        r = isolate_first_root(p, n, skin, T, failed_w)
        if r is CLEARED:
            return None
        if isinstance(r, tuple):
            return r
        lo = r
    hit = derivative_method(p, n, lo, T, 0.0, skin)
    return None if hit is None else (*hit, True)
