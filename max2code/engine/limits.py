"""What the engine's arithmetic can hold: the ranges every number of a scene is checked against.

The engine multiplies a scene's quantities together: a contact polynomial of degree 8 (a body
turning against an edge) has coefficients that are products of up to ten of them (omega^8
times a length squared), an impulse is a mass times a speed, an energy a mass times a speed
squared. With every given number 0 or between 1e-30 and 1e30 in magnitude, none of those
products overflows (1e300) or underflows to 0 (1e-300) in a double; the numbers derived from
the shapes get the room of their units (a mass is a density times an area, an inertia a mass
times a length squared). A float's spacing also bounds the lengths: a body farther than 2^45
tolerances from the origin has coordinates whose rounding (one ulp) exceeds 1/128 of the
tolerance, the contact slack the engine works within, so it is refused with a hint to raise
the tolerance. Before these limits, a mass of 1e308 gave an infinite impulse and a static
floor a NaN pose, and a capsule 1e15 long at a tolerance of 1e-9 never finished its step.
"""

from __future__ import annotations

import math
import numbers

LARGEST = 1e30          # a given number's magnitude at most this ...
SMALLEST = 1e-30        # ... and 0 or at least this
SPAN = 2.0 ** 45        # lengths from the origin: at most SPAN tolerances
MASS = (1e-30, 1e30)    # a dynamic body's mass, given or derived (density x area)
INERTIA = (1e-90, 1e90)  # its moment of inertia, given or derived (mass x length^2)
MAX_EVENTS = 2**62       # World(max_events=) and a scene's engine.max_events: at most this
CONTACT_STEP = 1 / 240  # the contact solver's default step h (docs/engine-contact.md): World's
                        # and scene files'; 0 turns it off (exact impacts and the rest rule)


def finite(v: object) -> bool:
    """A float, or an int a float holds (math.isfinite raises OverflowError on a larger one)."""
    try:
        return math.isfinite(v)  # type: ignore[arg-type]
    except (OverflowError, TypeError):
        return False


def shown(v: object, limit: int = 80) -> str:
    """repr cut to a length a message can carry (an int of a thousand digits is data too)."""
    text = repr(v)
    return text if len(text) <= limit else text[:limit - 3] + "..."


def number_problem(v: object, *, positive: bool = False, nonneg: bool = False,
                   lo: float | None = None, hi: float | None = None) -> str | None:
    """Why `v` is not a number the engine can take, or None: a real number (not a bool, not a
    string), finite, within magnitude_problem's range and the quantity's own bounds. One rule
    for scene files (Checker.number) and the Python API (World's arguments)."""
    if isinstance(v, bool) or not isinstance(v, numbers.Real) or not finite(v):
        return f"expected a finite number, got {shown(v)}"
    x = float(v)
    problem = magnitude_problem(x)
    if problem:
        return problem
    if positive and not x > 0:
        return f"must be positive, got {x:g}"
    if nonneg and x < 0:
        return f"must not be negative, got {x:g}"
    if lo is not None and hi is not None and not lo <= x <= hi:
        return f"must be between {lo:g} and {hi:g}, got {x:g}"
    return None


def magnitude_problem(v: float) -> str | None:
    """Why a finite number is out of the range the engine's products hold, or None."""
    if abs(v) > LARGEST:
        return (f"{v:g} is too large for the engine's arithmetic: at most {LARGEST:g} in "
                f"magnitude (its products must stay finite)")
    if v != 0 and abs(v) < SMALLEST:
        return (f"{v:g} is too small for the engine's arithmetic: 0, or at least {SMALLEST:g} "
                f"in magnitude (its products must not vanish)")
    return None


def range_problem(what: str, v: float, bounds: tuple[float, float]) -> str | None:
    """Why a derived quantity (a mass, an inertia) is out of its range, or None."""
    lo, hi = bounds
    if not (lo <= v <= hi):
        return (f"its {what} {v:.3g} is out of the range the engine's arithmetic holds "
                f"({lo:g} to {hi:g})")
    return None


def span_problem(reach: float, tolerance: float) -> str | None:
    """Why a body reaching `reach` from the origin is too far for the tolerance, or None."""
    if reach > SPAN * tolerance:
        return (f"reaches {reach:.3g} from the origin, farther than 2^45 tolerances "
                f"({SPAN * tolerance:.3g} at tolerance {tolerance:g}): its coordinates would round "
                f"by more than the contact slack; raise the tolerance or bring it nearer the origin")
    return None
