"""Regenerate tests/vectors/<equation stem>.jsonl for every shipped equation (equations/*.mxm)
and for the higher-order orbit models (bench/models/orbit-taylor6/8.mxm: degrees 12 and 16,
the circles-orbit cases).

    python tests/vectors/make_vectors.py            # all of them
    python tests/vectors/make_vectors.py circles-accel

The answers come from the independent oracle (max2code/commands/oracle.py): Maxima runs the ORIGINAL .mxm
program with the parameters substituted as exact rationals (every double is one) and expands
the polynomial in t exactly; the first root in (0, tmax] comes from mpmath at 60 digits, and
whether it is a multiple root (a graze) from an exact gcd of p and p'. Nothing of max2code's
coefficient extraction, printers or templates is used. The output is deterministic.

The file format is max2code/commands/vectors.py's (the one `max2code vectors` writes for any equation);
these hand-made cases add what only knowing the motion can build. The families and what each
case is meant to exercise are listed in FAMILIES below.
"""

from __future__ import annotations

import sys
import zlib
from fractions import Fraction
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
sys.path.insert(0, str(ROOT))

from max2code.commands import oracle, vectors  # noqa: E402
from max2code.codegen.generate import load  # noqa: E402
from max2code.commands.vectors import random_samples  # noqa: E402

TMAX = vectors.TMAX
FAMILIES = {
    "generic": "random game-like parameters (max2code/commands/vectors.py's random_samples), general variant",
    "no_root": "separating, passing wide, or colliding only after tmax",
    "graze": "closest approach exactly at contact, exact binary values: a double root",
    "cluster": "two (or four) roots close together: a shallow clip",
    "degree_drop": "equal accelerations (top coefficients vanish exactly) or role parameters "
                   "exactly zero (a variant is chosen)",
    "near_zero": "bodies 1e-9 apart and closing: a root near 1e-9",
    "scale": "one colliding case with every length scaled by 1e-8, 1e-4, 1e4 or 1e8",
    "far": "one colliding case translated to about 1e8 from the origin",
}
SCALES = (1e-8, 1e-4, 1e4, 1e8)
# The orbit models of order 6 and 8 (degree 12 and 16): circles-orbit's parameters and cases.
HIGH_ORDER = ("orbit-taylor6", "orbit-taylor8")
FAR = 1e8


# ---------------------------------------------------------------------------------------------
# The cases, per equation, in terms of what the bodies do
# ---------------------------------------------------------------------------------------------

def circles(orbit: bool):
    """Cases for two circles (circles-accel, or circles-orbit with orbit=True)."""
    pos = ("cx", "cy") if orbit else ("x", "y")

    def body(k: int, x=0.0, y=0.0, vx=0.0, vy=0.0, ax=0.0, ay=0.0, r=0.5, ox=0.0, oy=0.0,
             w=0.0) -> dict[str, float]:
        d = {f"{pos[0]}{k}": x, f"{pos[1]}{k}": y, f"vx{k}": vx, f"vy{k}": vy, f"ax{k}": ax,
             f"ay{k}": ay, f"r{k}": r}
        if orbit:
            d.update({f"ox{k}": ox, f"oy{k}": oy, f"w{k}": w})
        elif ox or oy or w:
            raise ValueError("no orbit here")
        return d

    def case(family: str, note: str, b1: dict, b2: dict, tmax: float = TMAX):
        return family, note, {**body(1, **b1), **body(2, **b2)}, tmax

    # An orbit common to both bodies cancels from their relative motion, so exact constructions
    # (grazes, clusters) keep the general octic variant in play for circles-orbit.
    spin = {"ox": 0.375, "oy": -0.25, "w": 0.25} if orbit else {}
    spin2 = {"ox": -0.5, "oy": 0.125, "w": -0.1875} if orbit else {}
    cases = [
        case("no_root", "moving apart", {"vx": -1.0, **spin}, {"x": 3.0, "vx": 0.5, **spin2}),
        case("no_root", "passing at twice the contact distance",
             {"vx": 1.0, **spin}, {"x": 5.0, "y": 2.0}),
        case("no_root", "collision at t = 20, after tmax = 10",
             {"vx": 0.25}, {"x": 6.0}),
        case("graze", "closest approach exactly r1 + r2 at t = 5",
             {"vx": 1.0, "r": 0.25, **spin}, {"x": 5.0, "y": 0.75, **spin}),
        case("graze", "accelerating: dx(t) = (t - 2)(t - 6)/2, touching at t = 2",
             {"ax": 1.0, "vx": -4.0, "r": 0.375, **spin}, {"x": -6.0, "y": -0.875, "r": 0.5,
                                                          **spin}),
        case("graze", "closest approach exactly r1 + r2 at t = 3, lengths 2^20",
             {"vx": 2.0 ** 20, "r": 2.0 ** 19, **spin},
             {"x": 3 * 2.0 ** 20, "y": 2.0 ** 20, "r": 2.0 ** 19, **spin}),
        case("graze", "closest approach exactly r1 + r2 at t = 3, lengths 2^-20",
             {"vx": 2.0 ** -20, "r": 2.0 ** -21}, {"x": 3 * 2.0 ** -20, "y": 2.0 ** -20,
                                                   "r": 2.0 ** -21}),
        case("cluster", "shallow clip: roots 2 +- 1.38e-3",
             {"vx": 1.0, "r": 0.5, **spin}, {"x": 2.0, "y": 1 - 2.0 ** -20, "r": 0.5, **spin}),
        case("cluster", "shallow clip: roots 4 +- 1.1e-5",
             {"vx": 0.5, "r": 0.5, **spin}, {"x": 2.0, "y": 1 - 2.0 ** -36, "r": 0.5, **spin}),
        case("degree_drop", "equal non-zero accelerations: the t^4 and t^3 terms vanish",
             {"ax": 0.75, "ay": -0.5, "vx": 1.0, **spin}, {"x": 4.0, "y": 0.5, "ax": 0.75,
                                                           "ay": -0.5, **spin}),
        case("degree_drop", "no acceleration (roles accel1, accel2): quadratic variant",
             {"vx": 1.5, "vy": 0.25}, {"x": 4.0, "y": 1.0, "vx": -0.5}),
        case("degree_drop", "a point and a circle (r1 = 0): the radius1 variant",
             {"vx": 1.0, "vy": 0.5, "r": 0.0}, {"x": 2.0, "y": -1.0, "vy": 1.0}),
        case("near_zero", "surfaces 1e-9 apart, closing at speed 1: root near 1e-9",
             {"vx": 1.0, **spin}, {"x": 1 + 1e-9, **spin}),
        case("near_zero", "surfaces 1e-9 apart at x ~ 3, closing at speed 2, diagonal",
             {"x": 3.0, "y": 3.0, "vx": 1.0, "vy": 1.0, "r": 0.25},
             {"x": 3 + (0.5 + 1e-9) / 2 ** 0.5, "y": 3 + (0.5 + 1e-9) / 2 ** 0.5,
              "vx": -1.0, "vy": -1.0, "r": 0.25}),
    ]
    if not orbit:
        # dx(t) = 16 (t - 2)^2 - e and dy = h, w = sqrt(R^2 - h^2) < e: four roots near t = 2.
        h = 1 - 2.0 ** -20
        cases.append(case("cluster", "four roots within 2 +- 0.017 (a parabola grazing the disc)",
                          {"ax": 32.0, "vx": -64.0, "r": 0.5},
                          {"x": -64.0 + 0.00275, "y": h, "r": 0.5}))
    if orbit:
        cases.append(case("generic", "both orbit, w1 = 0.5, w2 = -0.375, accelerating",
                          {"vx": 1.0, "ay": 0.25, "ox": 0.5, "w": 0.5},
                          {"x": 4.0, "y": 0.5, "ax": -0.5, "oy": 0.75, "w": -0.375}))
        cases.append(case("degree_drop", "orbiting with zero offsets: general variant, degree 4",
                          {"vx": 1.0, "ay": 0.25, "w": 0.5}, {"x": 4.0, "y": 0.5, "w": -0.375}))
        cases.append(case("degree_drop", "no orbit (w1 = w2 = 0): the quartic variant",
                          {"vx": 1.0, "ay": 0.25, "ox": 0.5}, {"x": 4.0, "y": 0.5, "ax": -0.5,
                                                               "oy": 0.75}))
    scaled = ({"vx": 1.0, "vy": 0.25, "ax": 0.125, "r": 0.5, **spin},
              {"x": 3.0, "y": 1.5, "vx": -0.5, "ay": -0.25, "r": 0.75, **spin2})
    positions = [f"{n}{k}" for k in (1, 2) for n in pos]
    return cases, case("", "", *scaled)[2], positions


def point_line(orbit: bool, radius: bool = False):
    """Cases for a point crossing a line (point-line, or point-orbit-line with orbit=True), or a
    circle of radius r reaching a rotating line (circle-orbit-line: radius=True)."""
    if orbit:
        p_names = {"x": "cpx", "y": "cpy", "vx": "vpx", "vy": "vpy", "ax": "apx", "ay": "apy",
                   "ox": "opx", "oy": "opy", "w": "wp"}
        l_names = {"x": "clx", "y": "cly", "vx": "vlx", "vy": "vly", "ax": "alx", "ay": "aly",
                   "ox": "olx", "oy": "oly", "w": "wl", "dx": "dx", "dy": "dy"}
    else:
        p_names = {"x": "px", "y": "py", "vx": "pvx", "vy": "pvy", "ax": "pax", "ay": "pay"}
        l_names = {"x": "lx", "y": "ly", "vx": "lvx", "vy": "lvy", "ax": "lax", "ay": "lay",
                   "dx": "dx", "dy": "dy"}

    if radius:
        p_names["r"] = "r"

    def case(family: str, note: str, p: dict, line: dict, tmax: float = TMAX):
        params = {n: 0.0 for n in [*p_names.values(), *l_names.values()]}
        params.update({p_names[k]: v for k, v in p.items()})
        params.update({l_names[k]: v for k, v in line.items()})
        return family, note, params, tmax

    vertical = {"dx": 0.0, "dy": 1.0}  # then p(t) = PX(t) - LX(t) (times C4(wl t) if rotating)
    spin_p = {"w": 0.25} if orbit else {}
    spin_l = {"w": -0.125} if orbit else {}
    cases = [
        case("no_root", "moving away from the line", {"x": 1.0, "vx": 1.0, **spin_p},
             {**vertical, **spin_l}),
        case("no_root", "moving parallel to the line", {"x": 1.0, "vx": 0.6, "vy": 0.8},
             {"dx": 0.6, "dy": 0.8}),
        case("no_root", "crossing at t = 16, after tmax = 10", {"x": 4.0, "vx": -0.25},
             vertical),
        case("graze", "the point's path touches the line at t = 2: (t - 2)^2",
             {"x": 4.0, "vx": -4.0, "ax": 2.0, **spin_p}, {**vertical, **spin_l}),
        case("graze", "touching at t = 3, lengths 2^20",
             {"x": 9 * 2.0 ** 20, "vx": -6 * 2.0 ** 20, "ax": 2 * 2.0 ** 20, "y": 5.0},
             {"dx": 0.0, "dy": 2.0 ** 20}),
        case("cluster", "roots 2 and 2 + 2^-10", {"x": 4 + 2 * 2.0 ** -10,
                                                  "vx": -(4 + 2.0 ** -10), "ax": 2.0, **spin_p},
             {**vertical, **spin_l}),
        case("cluster", "roots 2 and 2 + 2^-20", {"x": 4 + 2 * 2.0 ** -20,
                                                  "vx": -(4 + 2.0 ** -20), "ax": 2.0},
             vertical),
        case("degree_drop", "equal non-zero accelerations: the t^2 term vanishes",
             {"x": 3.0, "vx": -1.0, "ax": 0.5, "ay": 0.25, **spin_p},
             {"dx": 0.6, "dy": 0.8, "ax": 0.5, "ay": 0.25, **spin_l}),
        case("degree_drop", "no acceleration (roles): the linear variant",
             {"x": 3.0, "y": 1.0, "vx": -1.0}, {"dx": 0.6, "dy": 0.8, "vy": 0.5}),
        case("near_zero", "1e-9 from the line, closing at speed 1",
             {"x": 3 + 1e-9, "vx": -1.0, **spin_p}, {"x": 3.0, **vertical, **spin_l}),
    ]
    if orbit:
        cases += [
            case("generic", "both orbit, offsets non-zero, slanted line",
                 {"x": 2.0, "vx": -0.5, "ox": 0.5, "oy": 0.25, "w": 0.375},
                 {"dx": 0.6, "dy": 0.8, "ox": -0.25, "w": -0.25, "ay": 0.125}),
            case("degree_drop", "orbiting with zero offsets: general variant, degree 6",
                 {"x": 2.0, "vx": -0.5, "ax": 0.25, "w": 0.375},
                 {"dx": 0.6, "dy": 0.8, "w": -0.25}),
            case("degree_drop", "no orbit (wp = wl = 0): the quadratic variant",
                 {"x": 2.0, "vx": -0.5, "ax": 0.25, "ox": 0.5},
                 {"dx": 0.6, "dy": 0.8, "oy": 0.5}),
        ]
    if radius:
        cases += [
            case("generic", "a circle of radius 0.25 against a rotating slanted line",
                 {"x": 2.0, "vx": -0.5, "ox": 0.5, "oy": 0.25, "w": 0.375, "r": 0.25},
                 {"dx": 0.6, "dy": 0.8, "ox": -0.25, "w": -0.25, "ay": 0.125}),
            case("graze", "a circle of radius 0.25 whose centre's path is 0.25 from the line at t = 2",
                 {"x": 4.25, "vx": -4.0, "ax": 2.0, "r": 0.25}, vertical),
            case("near_zero", "a circle of radius 0.5 1e-9 from the line, closing at speed 1",
                 {"x": 3.5 + 1e-9, "vx": -1.0, "r": 0.5, **spin_p}, {"x": 3.0, **vertical, **spin_l}),
            case("degree_drop", "a circle, no orbit, no acceleration (roles): the linear variant",
                 {"x": 3.0, "y": 1.0, "vx": -1.0, "r": 0.5}, {"dx": 0.6, "dy": 0.8, "vy": 0.5}),
        ]
    scaled = case("", "", {"x": 1.0, "y": 0.5, "vx": -1.5, "vy": 0.25, "ax": 0.125, **spin_p},
                  {"dx": 0.6, "dy": 0.8, "x": -0.5, "vy": 0.5, "ax": -0.0625, **spin_l})[2]
    positions = [p_names["x"], p_names["y"], l_names["x"], l_names["y"]]
    return cases, scaled, positions


def equation_cases(stem: str, names: tuple[str, ...]) -> list[tuple[str, str, dict, float]]:
    """All cases of one equation, in a fixed order: (family, note, params, tmax)."""
    if stem.startswith("circles") or stem in HIGH_ORDER:
        cases, scaled_case, positions = circles(stem == "circles-orbit" or stem in HIGH_ORDER)
    else:
        cases, scaled_case, positions = point_line(stem in ("point-orbit-line", "circle-orbit-line"),
                                                   radius=stem == "circle-orbit-line")
    assert set(scaled_case) == set(names), sorted(set(scaled_case) ^ set(names))
    out = []
    seed = zlib.crc32(stem.encode())
    for sample in random_samples(names, 8, seed):
        out.append(("generic", "random", dict(zip(names, sample)), TMAX))
    out += [c for c in cases if c[0] == "generic"]
    out += [c for c in cases if c[0] != "generic"]
    # Lengths scale; angular velocities (w*) do not. Times, and so the roots, stay put.
    for s in SCALES:
        out.append(("scale", f"lengths times {s:g}",
                    {n: (v if n.startswith("w") else v * s) for n, v in scaled_case.items()},
                    TMAX))
    # Far from the origin (the expanded coefficients' cancellation case): the same geometry,
    # every position shifted (exactly: the positions are multiples of 2^-4).
    for shift in (FAR, -FAR * 1.25):
        moved = {n: (v + shift if n in positions else v) for n, v in scaled_case.items()}
        assert all(moved[n] - shift == scaled_case[n] for n in positions)
        out.append(("far", f"every position shifted by {shift:g}", moved, TMAX))
    for family, *_ in out:
        assert family in FAMILIES, family
    return out


# ---------------------------------------------------------------------------------------------
# Exact answers
# ---------------------------------------------------------------------------------------------

def vectors_for(mxm: Path) -> list[dict]:
    spec, poly = load(str(mxm))
    names = poly.parameters
    cases = [vectors.Case(family, note, params, tmax)
             for family, note, params, tmax in equation_cases(mxm.stem, names)]
    lines = []
    for case, line in vectors.answer(spec, names, poly.degree, cases, timeout=600):
        assert line is not None, case
        cs = [Fraction(c) for c in line["coefficients"]]
        roots = oracle.real_roots(cs, case.tmax)
        check_intent(mxm.stem, case.family, case.note, cs, roots, line["graze"], poly.degree)
        lines.append(line)
    return lines


def check_intent(stem: str, family: str, note: str, cs: list[Fraction], roots: list,
                 graze: bool, degree: int) -> None:
    """Each constructed case does what its family says, or the generator stops."""
    where = f"{stem}: {family}: {note}"
    if family == "no_root":
        assert not roots, where
    elif family == "graze":
        assert roots and graze, where
    else:
        assert not graze, where
    if family == "cluster":
        assert len(roots) >= 2 and roots[1] - roots[0] < 1e-2, (where, roots)
    if family == "near_zero":
        assert roots and 1e-10 < roots[0] < 1e-8, (where, roots)
    if family in ("scale", "far"):
        assert roots, where
    if family == "degree_drop" and "variant" not in note:
        top = max(k for k, c in enumerate(cs) if c != 0)
        assert top < degree, (where, top)


def text(mxm: Path) -> str:
    """The whole vector file of one equation."""
    _, poly = load(str(mxm))
    head = vectors.header(mxm.relative_to(ROOT).as_posix(), poly.parameters, FAMILIES,
                          "tests/vectors/make_vectors.py")
    return vectors.text(head, vectors_for(mxm))


def write(mxm: Path) -> Path:
    out = HERE / f"{mxm.stem}.jsonl"
    out.write_text(text(mxm))
    return out


def main(argv: list[str]) -> int:
    equations = sorted((ROOT / "equations").glob("*.mxm"))
    equations += [ROOT / "bench" / "models" / f"{stem}.mxm" for stem in HIGH_ORDER]
    if argv:
        equations = [e for e in equations if e.stem in argv]
    for mxm in equations:
        out = write(mxm)
        print(f"{out.relative_to(ROOT)}: {sum(1 for _ in out.open()) - 1} vectors")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
