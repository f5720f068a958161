"""An independent oracle: Maxima evaluates the ORIGINAL equation at exact rational parameters.

Nothing here uses max2code's coefficient extraction, printers or templates: the user's program
is run as written, the parameters are substituted as exact rationals (every double is one), and
Maxima expands the resulting polynomial in t exactly. Roots come from mpmath at 60 digits.
"""

from __future__ import annotations

import math
import random
import zlib
import re
import subprocess
import tempfile
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path

import mpmath

from max2code.parse import parse_file


@dataclass(frozen=True)
class Exact:
    params: tuple[float, ...]
    coefficients: tuple[Fraction, ...]  # index = power of t

    def first_root(self, tmax: float) -> tuple[float | None, float]:
        """Smallest real root in (0, tmax] and its conditioning scale |p|/|p'| bound."""
        return first_root_exact(self.coefficients, tmax)


def _frac(x: float) -> str:
    f = Fraction(x)
    return f"({f.numerator}/{f.denominator})"


def exact_coefficients(mxm: str | Path, names: tuple[str, ...],
                       samples: list[tuple[float, ...]]) -> list[Exact]:
    spec = parse_file(str(mxm))
    t = spec.variable
    lines = ["display2d:false$", "linel:1000000$"]
    lines += [s.text for s in spec.program.statements]
    lines += ["o__e: %$", "o__e: ev(o__e, nouns)$",
              'o__e: if not atom(o__e) and op(o__e) = "=" then lhs(o__e) - rhs(o__e) else o__e$']
    for i, sample in enumerate(samples):
        subst = ", ".join(f"{n} = {_frac(v)}" for n, v in zip(names, sample))
        lines.append(f"o__x: ratexpand(subst([{subst}], o__e))$")
        lines.append(f'printf(true, "~%ORACLE {i} ~a~%", string(makelist(ratcoef(o__x, {t}, k), '
                     f"k, 0, hipow(o__x, {t}))))$")
    with tempfile.TemporaryDirectory() as tmp:
        script = Path(tmp) / "oracle.mac"
        script.write_text("\n".join(lines) + "\n")
        out = subprocess.run(["maxima", "--very-quiet", "-b", str(script)], capture_output=True,
                             text=True, stdin=subprocess.DEVNULL, timeout=600, cwd=tmp).stdout
    found = dict(re.findall(r"^ORACLE (\d+) \[(.*)\]$", out, re.M))
    assert len(found) == len(samples), out[-2000:]
    result = []
    for i, sample in enumerate(samples):
        coefs = tuple(Fraction(c.strip()) for c in found[str(i)].split(","))
        result.append(Exact(sample, coefs))
    return result


def first_root_exact(coefficients: tuple[Fraction, ...], tmax: float) -> tuple[float | None, float]:
    """(root or None, |p'(root)|) of the exact polynomial, roots at 60 significant digits."""
    mpmath.mp.dps = 60
    cs = list(coefficients)
    while cs and cs[-1] == 0:
        cs.pop()
    while cs and cs[0] == 0:  # a root at exactly 0 is not in (0, tmax]
        cs.pop(0)
    if len(cs) < 2:
        return None, 0.0
    poly = [mpmath.mpf(c.numerator) / c.denominator for c in reversed(cs)]
    roots = mpmath.polyroots(poly, maxsteps=400, extraprec=400)
    best = None
    for r in roots:
        re_, im = mpmath.re(r), mpmath.im(r)
        if abs(im) <= mpmath.mpf(10) ** -30 * max(1, abs(re_)) and 0 < re_ <= tmax:
            best = re_ if best is None or re_ < best else best
    if best is None:
        return None, 0.0
    n = len(poly) - 1
    deriv = mpmath.polyval([poly[i] * (n - i) for i in range(n)], best)
    return float(best), float(abs(deriv))


def random_samples(names: tuple[str, ...], count: int, seed: int) -> list[tuple[float, ...]]:
    """Parameters on a game-like scale: positions within 5, speeds 3, accelerations 1, radii
    0.1..1, angular velocities 0.5 (so |w t| stays within the Taylor series' comfort)."""
    rng = random.Random(seed)
    out = []
    for i in range(count):
        spread = 5.0 if i % 2 else 1.5  # every other sample starts close: collisions happen
        values = []
        for n in names:
            if n.startswith("r"):
                values.append(rng.uniform(0.1, 1.0))
            elif n.startswith("w"):
                values.append(rng.uniform(-0.5, 0.5))
            elif n.startswith(("v", "pv", "lv")):
                values.append(rng.uniform(-3, 3))
            elif n.startswith(("a", "pa", "la")):
                values.append(rng.uniform(-1, 1))
            else:
                values.append(rng.uniform(-spread, spread))
        out.append(tuple(values))
    return out


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
    from max2code.generate import load

    spec, poly = load(str(path))
    samples = random_samples(poly.parameters, count, seed=zlib.crc32(path.stem.encode()))
    exact = exact_coefficients(path, poly.parameters, samples)
    hits = sum(1 for e in exact if e.first_root(TMAX)[0] is not None)
    assert 20 <= hits <= count - 20, f"{hits} of {count} samples collide: too one-sided a test"
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
