"""`max2code roles FILE.mxm`: which parameters, alone or in groups, are worth a role.

Candidates, each set to zero in one Maxima session:
* every parameter alone;
* the components of one vector, found by name: parameters whose names differ in one x/y/z
  letter (`ax1, ay1, az1`; `px, py`);
* groups found by measured effect: the parameters of candidates above that are worth a role
  and change the polynomial in the same way (the same degree and operation count), zeroed
  together: `ax1, ay1` and `ax2, ay2` (two bodies' accelerations), `w1` and `w2`;
* with --pairs, every pair.
A candidate is suggested when it would make a variant that is kept (variants.cheaper: a lower
degree, or at least 10% and 3 operations fewer than the general polynomial, optimised), and a
group only when it does better than each of its members alone (a group that merely contains a
good single is no news). `--all` lists every candidate with its effect.
A head start for writing `role` lines in a new equation, not a substitute for knowing the motion.
"""

from __future__ import annotations

import argparse
import itertools
import re
import sys
from dataclasses import dataclass

from ..diagnostics import Max2CodeError
from ..front.parse import parse_file
from ..codegen.poly import polynomial
from ..codegen.variants import cheaper, straight


@dataclass(frozen=True)
class Candidate:
    zeros: tuple[str, ...]
    kind: str  # "single", "vector", "effect", "pair"
    name: str  # a suggested role name
    degree: int
    ops: int
    useful: bool  # what a variant needs to be kept: variants.cheaper


def vector_groups(params: tuple[str, ...]) -> list[tuple[str, tuple[str, ...]]]:
    """(stem, members) for parameters whose names differ only in one x/y/z letter, in
    parameter order: ("a?1", ("ax1", "ay1", "az1"))."""
    groups: dict[str, list[str]] = {}
    for p in params:
        for m in re.finditer(r"[xyz]", p):
            groups.setdefault(p[:m.start()] + "?" + p[m.end():], []).append(p)
    seen: set[tuple[str, ...]] = set()
    out = []
    for stem, members in groups.items():
        group = tuple(members)
        if len(group) >= 2 and group not in seen:
            seen.add(group)
            out.append((stem, group))
    return out


def _measure(spec, timeout: float, combos: list[tuple[str, tuple[str, ...]]]
             ) -> tuple[int, int, dict[tuple[str, ...], tuple[int, int]]]:
    """(general degree, general operations, {zeros: (degree, operations)}) in one session."""
    unique = list(dict.fromkeys(zeros for _, zeros in combos))
    poly = polynomial(spec, timeout, combos=[((), ())] + [(z, z) for z in unique])
    effects = {v.zeros: (v.degree, straight(v, "optimised").ops.total) for v in poly.variants}
    return poly.degree, straight(poly, "optimised").ops.total, effects


def suggest(path: str, timeout: float, pairs: bool = False) -> tuple[int, int, list[Candidate]]:
    """(general degree, general operations, every candidate measured), best first."""
    spec = parse_file(path)
    params = polynomial(spec, timeout, combos=[((), ())]).parameters
    combos = [("single", (p,)) for p in params]
    combos += [("vector", group) for _, group in vector_groups(params)]
    stems: dict[tuple[str, ...], str] = {group: stem.replace("?", "")
                                          for stem, group in vector_groups(params)}
    degree, ops, effects = _measure(spec, timeout, combos)
    # By effect: candidates worth a role that change the polynomial alike, together.
    by_effect: dict[tuple[int, int], list[tuple[str, ...]]] = {}
    for _, zeros in combos:
        effect = effects.get(zeros)
        if effect is not None and cheaper(*effect, degree, ops):
            if not any(set(zeros) <= set(z) for z in by_effect.get(effect, [])):
                by_effect.setdefault(effect, []).append(zeros)
    more = []
    for members in by_effect.values():
        if len(members) >= 2:
            group = tuple(dict.fromkeys(p for z in members for p in z))
            stems[group] = "_".join(stems.get(z, z[0]) for z in members)
            more.append(("effect", group))
    if pairs:
        more += [("pair", pq) for pq in itertools.combinations(params, 2)]
    if more:
        _, _, later = _measure(spec, timeout, more)
        effects.update(later)
    out: dict[tuple[str, ...], Candidate] = {}
    for kind, zeros in combos + more:
        if zeros in out or zeros not in effects:
            continue  # measured already, or nothing left of the polynomial
        d, o = effects[zeros]
        useful = cheaper(d, o, degree, ops)
        name = stems.get(zeros) or "_".join(zeros)
        out[zeros] = Candidate(zeros, kind, name, d, o, useful)
    singles = {c.zeros[0]: (c.degree, c.ops) for c in out.values() if len(c.zeros) == 1}
    ranked = sorted(out.values(), key=lambda c: (c.degree, c.ops, len(c.zeros), c.zeros))
    return degree, ops, [replace_useful(c, singles, degree) for c in ranked]


def replace_useful(c: Candidate, singles: dict[str, tuple[int, int]], degree: int) -> Candidate:
    """A group is only news when it does better than each of its members alone."""
    if len(c.zeros) == 1 or not c.useful:
        return c
    better = all((c.degree, c.ops) < singles.get(p, (degree + 1, 0)) for p in c.zeros)
    return c if better else Candidate(c.zeros, c.kind, c.name, c.degree, c.ops, False)


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(prog="max2code roles", description=__doc__.splitlines()[0])
    ap.add_argument("input", metavar="FILE.mxm")
    ap.add_argument("--all", action="store_true",
                    help="list every candidate measured, not only the suggestions")
    ap.add_argument("--pairs", action="store_true",
                    help="also try every pair of parameters (n(n-1)/2 more polynomials)")
    from .options import add_maxima_options, apply_maxima_options
    add_maxima_options(ap)
    opts = ap.parse_args(argv)
    apply_maxima_options(opts)
    try:
        degree, ops, candidates = suggest(opts.input, opts.timeout, opts.pairs)
        existing = {tuple(sorted(r.params)): r.name for r in parse_file(opts.input).roles}
    except Max2CodeError as exc:
        for diag in exc.diagnostics:
            print(diag, file=sys.stderr)
        return 1
    print(f"{opts.input}: general polynomial of degree {degree}, {ops} operations (optimised)")
    shown = [c for c in candidates if c.useful or opts.all]
    if not any(c.useful for c in candidates):
        print("no parameter or group lowers the degree or saves 10% (and 3) of the operations")
    for c in shown:
        line = (f"  role {c.name} = {', '.join(c.zeros)}".ljust(44)
                + f" degree {c.degree}, {c.ops} operations ({c.ops - ops:+d}; {c.kind})")
        if not c.useful:
            line += " -- not worth a role"
        if tuple(sorted(c.zeros)) in existing:
            line += f" -- already role {existing[tuple(sorted(c.zeros))]}"
        print(line)
    return 0
