"""The quadratic kernel (quad_roots) of the C runtime against the pure-Python port's: the same numbers.

quad_roots scales a x^2 + b x + c by the power of two that brings the largest coefficient into
[1, 2), then forms the discriminant with error-free products.  The C runtime reads the exponent
from the bits and scales by multiplying with an exact power of two (no ilogb, ldexp, fmax or
fmin: library calls that were a fifth of a quadratic solve's instructions); the Python port
keeps ilogb and ldexp.  Multiplying by an exact power of two rounds as ldexp does, also where
the result is subnormal; where the power itself is not a normal number (the largest coefficient
below 2^-1023, or at 2^1023) C falls back to ldexp.  So every root and discriminant must be the
same number as Python's -- checked on random coefficients over the whole exponent range,
subnormals, zeros, signs, double roots and the two ends of that fallback.  (Zeros may differ in
sign: which of +0 and -0 comes first does not matter, a root must be above 0.)
"""
from __future__ import annotations

import math
import random
import sys
from pathlib import Path

from .c_program import run_c_program

PROGRAM = r"""
#include "max2code_roots.c"
#include <stdio.h>
#include <stdlib.h>

/* stdin: a line per quadratic, A B C (hex floats); prints the count, the discriminant and
 * the roots, one line each */
int main(void)
{
    char line[512];
    long total = 0;
    while (fgets(line, sizeof line, stdin)) {
        char *p = line, *end;
        double a = strtod(p, &end), b = strtod(end, &p), c = strtod(p, &end);
        double r[2] = {0, 0}, disc;
        int k = quad_roots(a, b, c, r, &disc);
        printf("%d %a %a %a\n", k, disc, r[0], r[1]);
        total++;
    }
    /* (run_c_program wants the last line; the comparison is Python's) */
    printf("%ld quadratics\n0 differences\n", total);
    return 0;
}
"""


def _coefficient(rng: random.Random) -> float:
    kind = rng.random()
    if kind < 0.05:
        return 0.0
    if kind < 0.12:  # subnormal
        x = rng.randint(1, 2**52 - 1) * 2.0**-1074
    elif kind < 0.2:  # near the top of the range
        x = math.ldexp(1 + rng.random(), rng.randint(1000, 1023))
    else:
        x = math.ldexp(1 + rng.random(), rng.randint(-1070, 1023))
    return -x if rng.random() < 0.5 else x


def _quadratics(count: int, seed: int) -> list[tuple[float, float, float]]:
    rng = random.Random(seed)
    out: list[tuple[float, float, float]] = []
    while len(out) < count:
        kind = rng.random()
        if kind < 0.6:
            a, b, c = (_coefficient(rng) for _ in range(3))
        elif kind < 0.8:  # real roots of every size: a (x - r1)(x - r2), rounded
            a = _coefficient(rng)
            r1, r2 = (math.ldexp(rng.uniform(-2, 2), rng.randint(-40, 40)) for _ in range(2))
            b, c = -a * (r1 + r2), a * r1 * r2
        elif kind < 0.9:  # double roots and touches: b^2 = 4 a c, up to rounding
            a = math.ldexp(1 + rng.random(), rng.randint(-60, 60))
            r = math.ldexp(1 + rng.random(), rng.randint(-60, 60))
            b, c = -2 * a * r, a * r * r
        else:  # the scaling's ends: the largest coefficient subnormal or at 2^1023
            top = rng.choice((rng.randint(1, 2**52 - 1) * 2.0**-1074,
                              math.ldexp(1 + rng.random(), 1023)))
            a, b, c = top, top * rng.random(), -top * rng.random()
            a, b, c = rng.sample((a, b, c), 3)
        if a != 0 and all(math.isfinite(x) for x in (a, b, c)):
            out.append((a, b, c))
    return out


def _same(x: float, y: float) -> bool:
    return x == y or (math.isnan(x) and math.isnan(y))


def test_quad_roots_as_the_python_port(tmp_path: Path) -> None:
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "runtime" / "python"))
    from max2code_runtime import solver

    quads = _quadratics(50_000, 20261203)
    out = run_c_program(PROGRAM, tmp_path, "quad_roots",
                        "".join(f"{a.hex()} {b.hex()} {c.hex()}\n" for a, b, c in quads))
    rows = out.splitlines()[:-2]
    assert len(rows) == len(quads)
    differ, real, fallback = [], 0, 0
    for (a, b, c), row in zip(quads, rows):
        k, disc, r0, r1 = row.split()
        roots, d = solver.quad_roots(a, b, c)
        got = (int(k), float.fromhex(disc)) + ((float.fromhex(r0), float.fromhex(r1)) if k == "2"
                                                else ())
        want = (2 if roots is not None else 0, d) + (tuple(roots) if roots is not None else ())
        real += roots is not None
        top = max(abs(a), abs(b), abs(c))
        fallback += top < 2.0**-1023 or top >= 2.0**1023
        if len(got) != len(want) or not all(_same(x, y) for x, y in zip(got, want)):
            differ.append(f"{a.hex()} {b.hex()} {c.hex()}: C {got}, Python {want}")
    assert not differ, f"{len(differ)} differ:\n" + "\n".join(differ[:10])
    assert 0.3 * len(quads) < real < 0.9 * len(quads) and fallback > 1000, (real, fallback)
