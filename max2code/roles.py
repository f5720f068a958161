"""`max2code roles FILE.mxm`: which parameters, alone or in pairs, are worth a role.

Each parameter, and each pair of parameters, is set to zero in one Maxima session; a candidate
is reported when it lowers the degree or saves at least 10% of the optimised operation count.
A head start for writing `role` lines in a new equation, not a substitute for knowing the motion.
"""

from __future__ import annotations

import argparse
import itertools
import sys

from . import maxima
from .diagnostics import Max2CodeError
from .parse import parse_file
from .poly import polynomial
from .variants import straight


def suggest(path: str, timeout: float, pairs: bool = True) -> list[tuple[tuple[str, ...], int, int]]:
    """(zero parameters, degree, operations) for every useful candidate, best first."""
    spec = parse_file(path)
    general = polynomial(spec, timeout, combos=[((), ())])
    params = general.parameters
    combos = [((), ())] + [((p,), (p,)) for p in params]
    if pairs:
        combos += [((p, q), (p, q)) for p, q in itertools.combinations(params, 2)]
    poly = polynomial(spec, timeout, combos=combos)
    base_ops = straight(poly, "optimised").ops.total
    found = []
    for v in poly.variants:
        ops = straight(v, "optimised").ops.total
        if v.degree < poly.degree or ops <= 0.9 * base_ops:
            found.append((v.zeros, v.degree, ops))
    # A pair is only news when neither of its members alone does as well.
    singles = {z[0]: (d, o) for z, d, o in found if len(z) == 1}
    kept = [(z, d, o) for z, d, o in found
            if len(z) == 1 or all((d, o) < singles.get(p, (poly.degree + 1, 0)) for p in z)]
    kept.sort(key=lambda r: (r[1], r[2], r[0]))
    return [((), poly.degree, base_ops)] + kept


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(prog="max2code roles", description=__doc__.splitlines()[0])
    ap.add_argument("input", metavar="FILE.mxm")
    ap.add_argument("--singles", action="store_true", help="try single parameters only")
    ap.add_argument("--timeout", type=float, default=maxima.DEFAULT_TIMEOUT)
    opts = ap.parse_args(argv)
    try:
        rows = suggest(opts.input, opts.timeout, not opts.singles)
    except Max2CodeError as exc:
        for diag in exc.diagnostics:
            print(diag, file=sys.stderr)
        return 1
    (_, degree, ops), rest = rows[0], rows[1:]
    print(f"{opts.input}: general polynomial of degree {degree}, {ops} operations (optimised)")
    if not rest:
        print("no parameter or pair lowers the degree or saves 10% of the operations")
    for zeros, d, o in rest:
        print(f"  role ? = {', '.join(zeros):<20} degree {d}, {o} operations ({o - ops:+d})")
    return 0
