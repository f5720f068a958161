"""Which variants a module carries, with their code under an evaluation strategy.

From every combination of roles Maxima gave a polynomial; here we keep the ones worth a branch:
a polynomial identical to a more general one is a duplicate, and a variant must be cheaper than
every variant it specialises (a lower degree, or at least 10% and 3 operations fewer), else the
more general code serves. The survivors are ordered cheapest first, which puts every variant
before the ones it specialises; the general polynomial (no conditions) is last and always holds.
"""

from __future__ import annotations

from dataclasses import dataclass

from .poly import Polynomial
from .straight import Ops, Straight
from .tpoly import NotPolynomial, optimise

STRATEGIES = ("optimised", "expanded")
DEFAULT_STRATEGY = "optimised"


@dataclass(frozen=True)
class Variant:
    """One branch of the generated selection code."""

    index: int
    poly: Polynomial
    code: Straight

    @property
    def zeros(self) -> tuple[str, ...]:
        return self.poly.zeros

    @property
    def roles(self) -> tuple[str, ...]:
        return self.poly.roles

    @property
    def degree(self) -> int:
        return self.poly.degree

    @property
    def ops(self) -> Ops:
        return self.code.ops

    @property
    def label(self) -> str:
        return "general" if not self.roles else "no " + ", no ".join(self.roles)


def straight(poly: Polynomial, strategy: str, prefix: str = "m2c_t") -> Straight:
    """The code for one polynomial. `expanded` is the paper's: Maxima's expanded coefficients."""
    if strategy == "optimised" and poly.unexpanded is not None:
        try:
            return optimise(poly.unexpanded, poly.variable, poly.degree, prefix)
        except NotPolynomial:
            pass  # Maxima's unexpanded form hides t somewhere only expansion removes
    return Straight((), poly.coefficients)


def cheaper(degree: int, ops: int, than_degree: int, than_ops: int) -> bool:
    """Worth a branch of its own: a lower degree, or at least 10% and 3 operations fewer."""
    if degree != than_degree:
        return degree < than_degree
    return ops <= 0.9 * than_ops and ops <= than_ops - 3


def _cheaper(v: Variant, u: Variant) -> bool:
    return cheaper(v.degree, v.ops.total, u.degree, u.ops.total)


def family(poly: Polynomial, strategy: str = DEFAULT_STRATEGY, prefix: str = "m2c_t",
           with_variants: bool = True) -> tuple[Variant, ...]:
    general = Variant(0, poly, straight(poly, strategy, prefix))
    candidates = [general]
    if with_variants:
        candidates += [Variant(0, v, straight(v, strategy, prefix)) for v in poly.variants]
    # Fewest conditions first, so a duplicate keeps its most general form.
    candidates.sort(key=lambda v: (len(v.zeros), v.zeros))
    kept: list[Variant] = []
    seen: set[tuple[object, ...]] = set()
    for v in candidates:
        if v.poly.coefficients in seen:
            continue
        generals = [u for u in kept if set(u.zeros) < set(v.zeros)]
        if v.zeros and not all(_cheaper(v, u) for u in generals):
            continue
        seen.add(v.poly.coefficients)
        kept.append(v)
    kept.sort(key=lambda v: (v.degree, v.ops.total, -len(v.zeros), v.zeros))
    return tuple(Variant(i, v.poly, v.code) for i, v in enumerate(kept))


def role_notes(poly: Polynomial, roles: dict[str, tuple[str, ...]], kept: tuple[Variant, ...],
               strategy: str = DEFAULT_STRATEGY, prefix: str = "m2c_t") -> dict[str, str]:
    """Why each role (name -> its parameters) that no kept variant carries yields none, so that
    a role never vanishes silently."""
    carried = {r for v in kept for r in v.roles}
    general = next(v for v in kept if not v.zeros)
    singles = {v.roles: v for v in poly.variants if len(v.roles) == 1}
    out = {}
    for name, params in roles.items():
        if name in carried:
            continue
        zeros = ", ".join(params)
        candidate = singles.get((name,))
        if candidate is None:
            out[name] = (f"with {zeros} zero no polynomial in {poly.variable} is left to solve "
                         f"(the equation vanishes or no longer depends on {poly.variable})")
            continue
        if candidate.coefficients == poly.coefficients:
            out[name] = f"it is the general polynomial ({zeros} zero changes nothing)"
            continue
        same = [v for v in kept if v.poly.coefficients == candidate.coefficients]
        if same:
            out[name] = f"it is the same polynomial as variant '{same[0].label}'"
            continue
        ops = straight(candidate, strategy, prefix).ops.total
        out[name] = (f"it is not cheaper than the general polynomial: degree {candidate.degree} "
                     f"and {ops} operations against degree {general.degree} and "
                     f"{general.ops.total} (a variant needs a lower degree, or 10% and 3 "
                     f"operations fewer)")
    return out
