"""The tests' side of the independent oracle (max2code/commands/oracle.py, which `max2code vectors` and
`max2code check` use too): Maxima evaluates the ORIGINAL equation at exact rational parameters,
mpmath finds the roots at 60 digits. Nothing of max2code's coefficient extraction, printers or
templates is involved. Here: samples as `Exact` values, and the bounds generated code is held to.
"""

from __future__ import annotations

import math
import zlib
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path

import mpmath

from max2code.commands import oracle
from max2code.front.parse import parse_file
from max2code.commands.vectors import random_samples  # noqa: F401 - the tests' samples come from here


@dataclass(frozen=True)
class Exact:
    params: tuple[float, ...]
    coefficients: tuple[Fraction, ...]  # index = power of t

    def first_root(self, tmax: float) -> tuple[float | None, float]:
        """Smallest real root in (0, tmax] and its conditioning scale |p|/|p'| bound."""
        return first_root_exact(self.coefficients, tmax)


def exact_coefficients(mxm: str | Path, names: tuple[str, ...],
                       samples: list[tuple[float, ...]]) -> list[Exact]:
    """The oracle's exact coefficients (max2code/commands/oracle.py) of each sample."""
    spec = parse_file(str(mxm))
    found = oracle.exact_coefficients(spec, names, samples, timeout=600)
    assert all(cs is not None for cs in found), "the oracle could not evaluate a sample"
    return [Exact(tuple(s), cs) for s, cs in zip(samples, found)]  # type: ignore[arg-type]


def first_root_exact(coefficients: tuple[Fraction, ...], tmax: float) -> tuple[float | None, float]:
    """(root or None, |p'(root)|) of the exact polynomial, roots at 60 significant digits."""
    root, _ = oracle.first_root(coefficients, tmax)
    if root is None:
        return None, 0.0
    cs = list(coefficients)
    deriv = sum(k * mpmath.mpf(c.numerator) / c.denominator * root ** (k - 1)
                for k, c in enumerate(cs) if k)
    return float(root), float(abs(deriv))


# Bounds for generated code against the oracle, shared by every language's test.
TMAX = 10.0
# Coefficient error, relative to the largest exact coefficient of the same sample: the fully
# expanded coefficients are sums of up to a few hundred products, each rounded once.
COEF_TOL = 1e-13
# Root error: relative 1e-10, plus what perturbing the coefficients by COEF_TOL (relative to
# the largest) moves a simple root by, |dp| / |p'(t)|.
ROOT_REL = 1e-10


def sampled_equation(path: Path, count: int):
    """(spec, poly, exact samples) for a shipped equation, with enough collisions and misses
    among the samples that both outcomes are tested."""
    from max2code.codegen.generate import load

    spec, poly = load(str(path))
    samples = random_samples(poly.parameters, count, seed=zlib.crc32(path.stem.encode()))
    exact = exact_coefficients(path, poly.parameters, samples)
    hits = sum(1 for e in exact if e.first_root(TMAX)[0] is not None)
    # A tenth of either outcome at least: a line (circle-orbit-line) is crossed by most motions,
    # so misses are rarer there than between two circles, but still tested.
    least = count // 10
    assert least <= hits <= count - least, f"{hits} of {count} samples collide: too one-sided a test"
    return spec, poly, exact


def check_sample(exact: Exact, coefs: list[float], root: float | None, label: str) -> None:
    """Coefficients within COEF_TOL of the exact ones; the first root within what that allows.

    The generated code may emit coefficients up to the general degree; the exact polynomial of
    a sample is shorter only where its top coefficients vanish, and those must come out ~0."""
    scale = max(abs(float(c)) for c in exact.coefficients)
    assert len(coefs) >= len(exact.coefficients), f"{label}: degree differs"
    padded = list(exact.coefficients) + [0] * (len(coefs) - len(exact.coefficients))
    for k, (got, want) in enumerate(zip(coefs, padded)):
        assert abs(got - float(want)) <= COEF_TOL * scale, (
            f"{label}: c[{k}] = {got!r}, exact {float(want)!r}")
    want_root, slope = exact.first_root(TMAX)
    if want_root is None:
        assert root is None, f"{label}: found {root!r}, exact polynomial has no root in (0, {TMAX}]"
        return
    spread = COEF_TOL * scale * sum(want_root ** k for k in range(len(coefs)))
    tol = ROOT_REL * want_root + (spread / slope if slope > 0 else math.inf)
    if root is None:
        # Only a root within rounding of the window's end, or of a double root, may be missed.
        assert TMAX - want_root <= tol or slope * want_root <= spread * 1e3, (
            f"{label}: missed root {want_root!r}")
        return
    assert abs(root - want_root) <= tol, f"{label}: root {root!r}, exact {want_root!r}"
