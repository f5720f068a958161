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

LARGEST = 1e30          # a given number's magnitude at most this ...
SMALLEST = 1e-30        # ... and 0 or at least this
SPAN = 2.0 ** 45        # lengths from the origin: at most SPAN tolerances
MASS = (1e-30, 1e30)    # a dynamic body's mass, given or derived (density x area)
INERTIA = (1e-90, 1e90)  # its moment of inertia, given or derived (mass x length^2)
CONTACT_STEP = 1 / 240  # the contact solver's default step h (docs/engine-contact.md): World's
                        # and scene files'; 0 turns it off (exact impacts and the rest rule)


def finite(v: object) -> bool:
    """A float, or an int a float holds (math.isfinite raises OverflowError on a larger one)."""
    try:
        return math.isfinite(v)  # type: ignore[arg-type]
    except (OverflowError, TypeError):
        return False


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
