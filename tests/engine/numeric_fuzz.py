"""Numeric-field fuzz of scene files (issue 33): every number of a scene that exercises every
field, replaced by a hostile value (NaN, +-inf, +-1e308, -0, subnormals, 10^400 as a float
and as an integer), must be refused with `file:line:col: error:` (exit 1) or run to its end
(exit 0, strict JSON on stdout), within a bounded wall time. One case is one `max2code sim`
subprocess with a timeout.

Used by tests/engine/test_scene_numeric_fuzz.py (hypothesis, CI-sized) and
bench/scene_numeric_fuzz.py (every field times every value, with counts).
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent.parent

# A scene with every numeric field: JSON-shaped, the numbers as text so a case can put any
# literal in one place.
BASE: dict = {
    "gravity": [0, -9.81], "tolerance": 1e-9, "until": 1, "fps": 30,
    "view": [-3, -1, 3, 4],
    "engine": {"cell_size": 0, "rest_speed": 0, "collapse_time": 0, "max_events": 0},
    "bodies": [
        {"name": "floor", "kind": "static", "shape": "segment", "points": [[-3, 0], [3, 0]],
         "radius": 0.01, "restitution": 0.9, "friction": 0.1},
        {"name": "ball", "shape": "circle", "position": [0, 1], "radius": 0.1,
         "offset": [0, 0], "velocity": [1, 2], "omega": 3, "angle": 0.5, "mass": 2,
         "inertia": 0.01, "restitution": 0.8, "friction": 0.2, "gravity": [0, -10]},
        {"name": "crate", "shape": "box", "position": [1.5, 1], "size": [0.4, 0.3],
         "angle": 0.1, "velocity": [-1, 0], "omega": -1, "density": 3, "radius": 0.01},
        {"name": "wedge", "shape": "polygon", "position": [-1.5, 1],
         "vertices": [[0, 0], [0.4, 0], [0.2, 0.3]], "velocity": [0.5, 0]},
        {"name": "paddle", "kind": "kinematic", "shape": "segment", "position": [0, 3],
         "points": [[-0.5, 0], [0.5, 0]], "radius": 0.05, "velocity": [0, -0.1], "omega": 0.5},
    ],
}

# the hostile values, as the literal each format writes (None: the format has none)
VALUES: dict[str, tuple[str | None, str | None]] = {   # name -> (JSON, TOML)
    "nan": (None, "nan"), "inf": (None, "inf"), "-inf": (None, "-inf"),
    "1e308": ("1e308", "1e308"), "-1e308": ("-1e308", "-1e308"), "-0": ("-0.0", "-0.0"),
    "min subnormal": ("5e-324", "5e-324"), "subnormal": ("1e-310", "1e-310"),
    "min normal": ("2.2250738585072014e-308", "2.2250738585072014e-308"),
    "1e400": ("1e400", "1e400"), "10^400 int": ("1" + "0" * 400, "1" + "0" * 400),
}


def fields(node: object = BASE, path: tuple = ()) -> list[tuple]:
    """The path of every number in BASE."""
    if isinstance(node, dict):
        return [p for k, v in node.items() for p in fields(v, path + (k,))]
    if isinstance(node, list):
        return [p for k, v in enumerate(node) for p in fields(v, path + (k,))]
    return [path] if isinstance(node, (int, float)) and not isinstance(node, bool) else []


def _json(node: object, path: tuple, target: tuple, literal: str) -> str:
    if path == target:
        return literal
    if isinstance(node, dict):
        return "{" + ", ".join(f"{json.dumps(k)}: {_json(v, path + (k,), target, literal)}"
                               for k, v in node.items()) + "}"
    if isinstance(node, list):
        return "[" + ", ".join(_json(v, path + (k,), target, literal)
                               for k, v in enumerate(node)) + "]"
    return json.dumps(node)


def _toml_value(node: object, path: tuple, target: tuple, literal: str) -> str:
    if path == target:
        return literal
    if isinstance(node, list):
        return "[" + ", ".join(_toml_value(v, path + (k,), target, literal)
                               for k, v in enumerate(node)) + "]"
    return json.dumps(node)  # numbers and strings are written alike


def _toml(target: tuple, literal: str) -> str:
    lines = []
    for key, value in BASE.items():
        if not isinstance(value, (dict, list)) or key == "view" or key == "gravity":
            lines.append(f"{key} = {_toml_value(value, (key,), target, literal)}")
    lines.append("\n[engine]")
    for key, value in BASE["engine"].items():
        lines.append(f"{key} = {_toml_value(value, ('engine', key), target, literal)}")
    for k, body in enumerate(BASE["bodies"]):
        lines.append("\n[[bodies]]")
        for key, value in body.items():
            lines.append(f"{key} = {_toml_value(value, ('bodies', k, key), target, literal)}")
    return "\n".join(lines) + "\n"


@dataclass(frozen=True)
class Outcome:
    field: str
    value: str
    fmt: str
    status: str        # refused, ran, or what went wrong
    seconds: float
    detail: str = ""


LOCATED = re.compile(r"^.+:\d+:\d+: error: ")


def run_case(folder: Path, target: tuple, value: str, fmt: str, timeout: float = 60) -> Outcome:
    """One case: the scene with the value at `target`, through `max2code sim --json`."""
    literal = VALUES[value][0 if fmt == "json" else 1]
    assert literal is not None
    path = folder / f"scene.{fmt}"
    path.write_text(_json(BASE, (), target, literal) if fmt == "json" else _toml(target, literal))
    name = ".".join(str(p) for p in target)
    start = time.monotonic()
    try:
        proc = subprocess.run([sys.executable, "-m", "max2code", "sim", str(path), "--json"],
                              capture_output=True, text=True, cwd=ROOT, timeout=timeout)
    except subprocess.TimeoutExpired:
        return Outcome(name, value, fmt, "timeout", time.monotonic() - start)
    seconds = time.monotonic() - start
    if proc.returncode == 1 and LOCATED.match(proc.stderr) and not proc.stdout:
        return Outcome(name, value, fmt, "refused", seconds, proc.stderr.splitlines()[0])
    if proc.returncode == 0:
        try:
            json.loads(proc.stdout, parse_constant=lambda c: (_ for _ in ()).throw(ValueError(c)))
            return Outcome(name, value, fmt, "ran", seconds)
        except ValueError as exc:
            return Outcome(name, value, fmt, "bad json", seconds, str(exc)[:200])
    return Outcome(name, value, fmt, f"exit {proc.returncode}", seconds,
                   (proc.stderr or proc.stdout)[-300:])


def cases() -> list[tuple[tuple, str, str]]:
    """Every field times every value, in each format that can write the value."""
    return [(f, v, fmt) for f in fields() for v, lits in VALUES.items()
            for fmt, lit in zip(("json", "toml"), lits) if lit is not None]
