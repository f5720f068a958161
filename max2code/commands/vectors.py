"""Test vectors: parameters with the exact answers of the independent oracle (oracle.py).

    max2code vectors FILE.mxm [-o FILE.jsonl] [--count N]

File format (one JSON object per line; the first line is a header):
  {"max2code_vectors": 1, "equation": "...", "parameters": [...], ...}
  {"family": F, "params": {name: value}, "tmax": T, "coefficients": [...], "first_root": R,
   "graze": G, "note": "..."}
* params: exact doubles, as a decimal string when that string is the double exactly ("0.75"),
  else a hex float ("0x1.0000000112e0be8p+0");
* tmax: a JSON number (an exact double);
* coefficients: the exact coefficients, c[k] multiplying t^k, as rational strings ("-3/8"),
  padded with zeros up to the equation's general degree;
* first_root: the smallest real root in (0, tmax] as a decimal string of 30 significant
  digits, or null;
* graze: true when that root is a multiple root (the bodies touch without crossing).

Any equation gets GENERIC_FAMILIES: random parameters on a game-like scale (by name: r* radii,
w* angular velocities, v* velocities, a* accelerations, the rest positions), each colliding one
again with tmax below its first root (no root in the window), and every variant the module
carries with its parameters exactly zero. The shipped equations have hand-made vectors besides
(tests/vectors/, from tests/vectors/make_vectors.py): grazes, clusters, scales.

`max2code check` makes a file this way when an equation has none, and keeps it in the cache
under a digest of the .mxm, the files it loads and this generator (`cached_vectors`).
"""

from __future__ import annotations

import argparse
import hashlib
import json
import math
import random
import sys
import zlib
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path
from typing import Any, Sequence

from .. import __version__, cache
from ..maxima import depfile, session as maxima
from ..diagnostics import Max2CodeError
from ..output import write_if_changed
from ..paths import display

FORMAT = 1
TMAX = 10.0
GENERIC_COUNT = 16
GENERIC_FAMILIES = {
    "generic": "random game-like parameters (by name: r* radii 0.1..1, w* angular velocities "
               "within 0.5, v* velocities within 3, a* accelerations within 1, the rest "
               "positions within 1.5 or 5)",
    "no_root": "a colliding generic case again, with tmax half its first root",
    "variant": "random parameters with one variant's parameters exactly zero",
}


# ---------------------------------------------------------------------------------------------
# Reading
# ---------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Vector:
    line: int
    family: str
    params: tuple[float, ...]
    tmax: float
    coefficients: tuple[Fraction, ...]
    first_root: Fraction | None
    graze: bool
    note: str = ""


class VectorError(Exception):
    pass


def parse_double(text: object) -> float:
    """An exact double from a vector file: a hex float, or a decimal string that is one exactly."""
    if isinstance(text, (int, float)):
        return float(text)
    s = str(text)
    if "0x" in s.lower():
        return float.fromhex(s)
    value = float(s)
    if math.isfinite(value) and Fraction(s) != Fraction(value):
        raise VectorError(f"{s!r} is not exactly a double (write it as a hex float)")
    return value


def load_vectors(path: Path, parameters: tuple[str, ...]) -> list[Vector]:
    """The vectors of one file, after its header; the header's parameters must be the module's.
    An empty list when the file holds none."""
    out = []
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except OSError as exc:
        raise VectorError(f"{path}: {exc.strerror}") from None
    for number, text in enumerate(lines, 1):
        if not text.strip():
            continue
        where = f"{path}:{number}"
        try:
            obj = json.loads(text)
        except json.JSONDecodeError as exc:
            raise VectorError(f"{where}: {exc}") from None
        if "max2code_vectors" in obj:
            if tuple(obj.get("parameters", parameters)) != tuple(parameters):
                raise VectorError(f"{where}: parameters {obj['parameters']} differ from the "
                                  f"equation's {list(parameters)}")
            continue
        try:
            params = obj["params"]
            if set(params) != set(parameters):
                raise VectorError(f"{where}: params name {sorted(params)}, the equation has "
                                  f"{sorted(parameters)}")
            root = obj["first_root"]
            out.append(Vector(
                line=number, family=str(obj["family"]),
                params=tuple(parse_double(params[n]) for n in parameters),
                tmax=parse_double(obj["tmax"]),
                coefficients=tuple(Fraction(str(c)) for c in obj["coefficients"]),
                first_root=None if root is None else Fraction(str(root)),
                graze=bool(obj.get("graze", False)), note=str(obj.get("note", ""))))
        except (KeyError, ValueError, TypeError) as exc:
            raise VectorError(f"{where}: bad vector: {exc!r}") from None
    return out


# ---------------------------------------------------------------------------------------------
# Writing
# ---------------------------------------------------------------------------------------------

def exact_value(x: float) -> str:
    """The double x exactly: a short decimal string when that is exact, else a hex float."""
    text = repr(float(x))
    return text if Fraction(text) == Fraction(x) else float.hex(x)


@dataclass(frozen=True)
class Case:
    """One vector to be answered by the oracle."""

    family: str
    note: str
    params: dict[str, float]
    tmax: float = TMAX


def answer(spec: Any, names: Sequence[str], degree: int, cases: Sequence[Case],
           timeout: float = maxima.DEFAULT_TIMEOUT) -> list[tuple[Case, dict | None]]:
    """Each case with its vector line (None where the equation cannot be evaluated there)."""
    from . import oracle

    mp = oracle.mpmath()
    samples = [tuple(float(c.params[n]) for n in names) for c in cases]
    exact = oracle.exact_coefficients(spec, names, samples, timeout)
    out: list[tuple[Case, dict | None]] = []
    for case, cs in zip(cases, exact):
        if cs is None:
            out.append((case, None))
            continue
        root, graze = oracle.first_root(cs, case.tmax)
        padded = list(cs) + [Fraction(0)] * (degree + 1 - len(cs))
        out.append((case, {
            "family": case.family,
            "params": {n: exact_value(case.params[n]) for n in names},
            "tmax": case.tmax,
            "coefficients": [str(c) for c in padded],
            "first_root": None if root is None else mp.nstr(root, 30),
            "graze": graze,
            "note": case.note,
        }))
    return out


def text(head: dict, lines: Sequence[dict]) -> str:
    return "".join(json.dumps(line) + "\n" for line in [head, *lines])


# ---------------------------------------------------------------------------------------------
# Vectors for any equation
# ---------------------------------------------------------------------------------------------

def random_samples(names: Sequence[str], count: int, seed: int) -> list[tuple[float, ...]]:
    """Parameters on a game-like scale: positions within 5, speeds 3, accelerations 1, radii
    0.1..1, angular velocities 0.5 (so |w t| stays within a Taylor series' comfort)."""
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


def generic_vectors(path: str, count: int = GENERIC_COUNT,
                    timeout: float = maxima.DEFAULT_TIMEOUT) -> str:
    """The whole vector file of any equation (deterministic: seeded by the file's bytes)."""
    from ..codegen.generate import load
    from ..codegen.variants import family

    spec, poly = load(path, timeout)
    names = poly.parameters
    seed = zlib.crc32(Path(path).read_bytes())
    cases = [Case("generic", "random", dict(zip(names, s)))
             for s in random_samples(names, count, seed)]
    variants = [v for v in family(poly) if v.zeros]
    for k, v in enumerate(variants):
        for s in random_samples(names, 2, seed + 1 + k):
            values = dict(zip(names, s))
            values.update({z: 0.0 for z in v.zeros})
            cases.append(Case("variant", f"{v.label} ({', '.join(v.zeros)} = 0)", values))
    answered = answer(spec, names, poly.degree, cases, timeout)
    lines = [line for _, line in answered if line is not None]
    # The colliding generic cases again, each with its window ending before its first root.
    for line in [x for x in lines if x["family"] == "generic" and x["first_root"]]:
        tmax = float(Fraction(line["first_root"]) / 2)
        if tmax > 0:
            lines.append({**line, "family": "no_root", "tmax": tmax, "first_root": None,
                          "graze": False, "note": "tmax half the first root"})
    families = {**GENERIC_FAMILIES}
    head = header(path, names, families, "max2code vectors")
    return text(head, lines)


def header(path: str, names: Sequence[str], families: dict[str, str], generator: str) -> dict:
    from .oracle import DIGITS

    return {
        "max2code_vectors": FORMAT,
        "equation": path,
        "parameters": list(names),
        "oracle": "max2code/commands/oracle.py: Maxima expands the original equation at exact rational "
                  f"parameters; first root by mpmath at {DIGITS} digits; graze by exact "
                  "gcd(p, p')",
        "generator": generator,
        "families": families,
        "tolerances": "max2code/commands/check.py (TOLERANCES)",
    }


def content_key(path: str) -> str | None:
    """A digest of what the vectors depend on: the .mxm, the files it loads, the generator
    (this module's and the oracle's code)."""
    h = hashlib.sha256(f"max2code-vectors {FORMAT} {GENERIC_COUNT} {__version__}\0".encode())
    for module in ("vectors.py", "oracle.py"):
        h.update(hashlib.sha256((Path(__file__).parent / module).read_bytes()).digest())
    try:
        h.update(hashlib.sha256(Path(path).read_bytes()).digest())
    except OSError:
        return None
    loads = depfile.loaded_files_of_source(path)
    for name in loads or ():
        try:
            h.update(hashlib.sha256(Path(name).read_bytes()).digest())
        except OSError:
            return None
    return h.hexdigest()


def cached_vectors(path: str, fallback: Path,
                   timeout: float = maxima.DEFAULT_TIMEOUT) -> tuple[Path, bool]:
    """The generic vectors of `path`, made once per content: (file, whether it was made now).
    Without a usable cache they are written into the folder `fallback`."""
    key = content_key(path)
    target = cache.directory() / "vectors" / f"{key}.jsonl" if key else None
    usable = target is not None and cache.enabled()
    if usable and target.is_file():  # type: ignore[union-attr]
        return target, False  # type: ignore[return-value]
    body = generic_vectors(path, timeout=timeout)
    if usable and body.count("\n") > 1:  # never keep a file without vectors
        try:
            target.parent.mkdir(parents=True, exist_ok=True)  # type: ignore[union-attr]
            write_if_changed(str(target), body)
            return target, True  # type: ignore[return-value]
        except (OSError, Max2CodeError):
            pass
    fallback.mkdir(parents=True, exist_ok=True)
    out = fallback / f"{Path(path).stem}-{key or 'vectors'}.jsonl"
    out.write_text(body, encoding="utf-8")
    return out, True


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(
        prog="max2code vectors",
        description="Test vectors for any equation: random parameters (and each variant's "
                    "parameters at zero) with the exact coefficients and first root from the "
                    "independent oracle (Maxima at exact rationals, mpmath roots; needs the "
                    "'oracle' extra). For `max2code check --vectors`.")
    ap.add_argument("input", metavar="FILE.mxm")
    ap.add_argument("-o", "--output", default="-", metavar="FILE.jsonl",
                    help="output file ('-' for standard output, the default)")
    ap.add_argument("--count", type=int, default=GENERIC_COUNT, metavar="N",
                    help=f"random parameter sets (default {GENERIC_COUNT})")
    from .options import add_maxima_options, apply_maxima_options
    add_maxima_options(ap)
    opts = ap.parse_args(argv)
    apply_maxima_options(opts)
    if opts.count < 1:
        ap.error("--count must be at least 1")
    try:
        body = generic_vectors(opts.input, opts.count, opts.timeout)
        write_if_changed(opts.output, body)
    except Max2CodeError as exc:
        for diag in exc.diagnostics:
            print(diag, file=sys.stderr)
        return 1
    if opts.output != "-":
        count = body.count("\n") - 1
        print(f"{opts.output}: {count} vectors for {display(Path(opts.input).resolve())}",
              file=sys.stderr)
    return 0
