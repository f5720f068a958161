"""Regenerate tests/vectors/<equation stem>.jsonl for every shipped equation (equations/*.mxm).

    python tests/vectors/make_vectors.py            # all shipped equations
    python tests/vectors/make_vectors.py circles-accel

The answers come from the independent oracle of tests/oracle.py: Maxima runs the ORIGINAL .mxm
program with the parameters substituted as exact rationals (every double is one) and expands
the polynomial in t exactly; the first root in (0, tmax] comes from mpmath at 60 digits, and
whether it is a multiple root (a graze) from an exact gcd of p and p'. Nothing of max2code's
coefficient extraction, printers or templates is used. The output is deterministic.

File format (one JSON object per line; the first line is a header):
  {"max2code_vectors": 1, "equation": "equations/NAME.mxm", "parameters": [...], ...}
  {"family": F, "params": {name: value}, "tmax": T, "coefficients": [...], "first_root": R,
   "graze": G, "note": "..."}
* params: exact doubles, as a decimal string when that string is the double exactly ("0.75"),
  else a hex float ("0x1.0000000112e0be8p+0");
* tmax: a JSON number (an exact double);
* coefficients: the exact coefficients, c[k] multiplying t^k, as rational strings ("-3/8");
  trailing zero coefficients are kept up to the equation's general degree;
* first_root: the smallest real root in (0, tmax] as a decimal string of 30 significant
  digits, or null;
* graze: true when that root is a multiple root (the bodies touch without crossing).
The families and what each case is meant to exercise are listed in FAMILIES below.
"""

from __future__ import annotations

import json
import sys
import zlib
from fractions import Fraction
from pathlib import Path

import mpmath

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
sys.path.insert(0, str(ROOT / "tests"))
sys.path.insert(0, str(ROOT))

from oracle import exact_coefficients, random_samples  # noqa: E402

from max2code.generate import load  # noqa: E402

TMAX = 10.0
DIGITS = 60
FAMILIES = {
    "generic": "random game-like parameters (tests/oracle.py's random_samples), general variant",
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
    if stem.startswith("circles"):
        cases, scaled_case, positions = circles(stem == "circles-orbit")
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

def exact_value(x: float) -> str:
    """The double x exactly: a short decimal string when that is exact, else a hex float."""
    text = repr(float(x))
    return text if Fraction(text) == Fraction(x) else float.hex(x)


def _trim(cs: list[Fraction]) -> list[Fraction]:
    cs = list(cs)
    while cs and cs[-1] == 0:
        cs.pop()
    return cs


def _rem(a: list[Fraction], b: list[Fraction]) -> list[Fraction]:
    a = _trim(a)
    while len(a) >= len(b):
        q = a[-1] / b[-1]
        shift = len(a) - len(b)
        for i, bc in enumerate(b):
            a[shift + i] -= q * bc
        a = _trim(a[:-1])
    return a


def gcd_poly(a: list[Fraction], b: list[Fraction]) -> list[Fraction]:
    a, b = _trim(a), _trim(b)
    while b:
        a, b = b, _rem(a, b)
    return a


def _div(a: list[Fraction], b: list[Fraction]) -> list[Fraction]:
    """The exact quotient a / b (b divides a)."""
    a, q = _trim(a), [Fraction(0)] * (len(_trim(a)) - len(b) + 1)
    while len(a) >= len(b):
        shift = len(a) - len(b)
        q[shift] = a[-1] / b[-1]
        for i, bc in enumerate(b):
            a[shift + i] -= q[shift] * bc
        a = _trim(a[:-1])
    assert not a, "not a divisor"
    return q


def real_roots(cs: list[Fraction], tmax: float) -> list[mpmath.mpf]:
    """The distinct real roots in (0, tmax] of the exact polynomial, ascending, at DIGITS: the
    roots of its square-free part p / gcd(p, p'), which are all simple (so converge fully)."""
    mpmath.mp.dps = DIGITS
    cs = _trim(cs)
    g = gcd_poly(cs, [k * c for k, c in enumerate(cs)][1:])
    if len(g) >= 2:
        cs = _div(cs, g)
    while cs and cs[0] == 0:
        cs.pop(0)
    if len(cs) < 2:
        return []
    poly = [mpmath.mpf(c.numerator) / c.denominator for c in reversed(cs)]
    roots = mpmath.polyroots(poly, maxsteps=800, extraprec=800)
    found = []
    for r in roots:
        re_, im = mpmath.re(r), mpmath.im(r)
        if abs(im) <= mpmath.mpf(10) ** -40 * max(1, abs(re_)) and 0 < re_ <= tmax:
            if not any(abs(re_ - f) <= mpmath.mpf(10) ** -35 * max(1, abs(re_)) for f in found):
                found.append(re_)
    return sorted(found)


def is_multiple(cs: list[Fraction], root: mpmath.mpf) -> bool:
    """Whether `root` is a multiple root: a root of gcd(p, p') (exact arithmetic)."""
    deriv = [k * c for k, c in enumerate(cs)][1:]
    g = gcd_poly(list(cs), deriv)
    if len(g) < 2:
        return False
    value = mpmath.polyval([mpmath.mpf(c.numerator) / c.denominator for c in reversed(g)], root)
    size = sum(abs(mpmath.mpf(c.numerator) / c.denominator) * abs(root) ** k
               for k, c in enumerate(g))
    return abs(value) <= mpmath.mpf(10) ** -30 * size


def vectors_for(mxm: Path) -> list[dict]:
    _, poly = load(str(mxm))
    names = poly.parameters
    cases = equation_cases(mxm.stem, names)
    samples = [tuple(float(params[n]) for n in names) for _, _, params, _ in cases]
    exact = exact_coefficients(mxm, names, samples)
    lines = []
    for (family, note, params, tmax), ex in zip(cases, exact):
        cs = list(ex.coefficients)
        assert len(cs) <= poly.degree + 1
        roots = real_roots(cs, tmax)
        first = roots[0] if roots else None
        graze = first is not None and is_multiple(cs, first)
        check_intent(mxm.stem, family, note, cs, roots, graze, poly.degree)
        padded = cs + [Fraction(0)] * (poly.degree + 1 - len(cs))
        lines.append({
            "family": family,
            "params": {n: exact_value(params[n]) for n in names},
            "tmax": tmax,
            "coefficients": [str(c) for c in padded],
            "first_root": None if first is None else mpmath.nstr(first, 30),
            "graze": graze,
            "note": note,
        })
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
        assert len(_trim(cs)) - 1 < degree, (where, len(_trim(cs)) - 1)


def header(mxm: Path, names: tuple[str, ...]) -> dict:
    return {
        "max2code_vectors": 1,
        "equation": mxm.relative_to(ROOT).as_posix(),
        "parameters": list(names),
        "oracle": "tests/oracle.py: Maxima expands the original equation at exact rational "
                  f"parameters; first root by mpmath at {DIGITS} digits; graze by exact "
                  "gcd(p, p')",
        "generator": "tests/vectors/make_vectors.py",
        "families": FAMILIES,
        "tolerances": "max2code/check.py (TOLERANCES)",
    }


def text(mxm: Path) -> str:
    """The whole vector file of one equation."""
    _, poly = load(str(mxm))
    lines = [header(mxm, poly.parameters), *vectors_for(mxm)]
    return "".join(json.dumps(line) + "\n" for line in lines)


def write(mxm: Path) -> Path:
    out = HERE / f"{mxm.stem}.jsonl"
    out.write_text(text(mxm))
    return out


def main(argv: list[str]) -> int:
    equations = sorted((ROOT / "equations").glob("*.mxm"))
    if argv:
        equations = [e for e in equations if e.stem in argv]
    for mxm in equations:
        out = write(mxm)
        print(f"{out.relative_to(ROOT)}: {sum(1 for _ in out.open()) - 1} vectors")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
