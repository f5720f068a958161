"""Modula-2: the generated NAME.def + NAME.mod compiled with gm2 -fiso -fcpp (the #line
directives), and a driver linked with the C runtime through Max2codeRoots.def (-L<m2iso>
-lm2iso -lpthread and GSL). Numbers travel as IEEE bit patterns, two 32-bit halves each in
decimal (the ISO library reads no hex): the driver reads the cases on standard input (cases
embedded in its source made gm2 take minutes on large modules), each line ending in a space
(gm2's ReadCard reports a number that ends a line as `endOfLine`, not `allRight`), and prints
each double as "lo:hi"."""

from __future__ import annotations

import shutil
import struct
from pathlib import Path

from ...paths import runtime_dir
from ..harness import Harness, Outcome, Unit, parse_lines, run, tool
from ..c.harness import LIBS, runtime_object


def halves(x: float) -> tuple[int, int]:
    """The low and high 32-bit halves of a double (little-endian x86-64 and ARM)."""
    return struct.unpack("<II", struct.pack("<d", x))


def from_halves(text: str) -> float:
    lo, hi = text.split(":")
    return struct.unpack("<d", struct.pack("<II", int(lo), int(hi)))[0]


class M2Harness(Harness):
    lang = "m2"
    tools = ("gm2", "gcc")

    def run(self, units: list[Unit], workdir: Path, build_dir: Path) -> dict[str, list[Outcome]]:
        gm2, gcc = tool("gm2"), tool("gcc")
        obj = runtime_object(gcc, workdir)
        iso = run([gm2, "-print-file-name=m2/m2iso"]).strip()
        results = {}
        for unit in units:
            folder, module = self.write_module(unit, workdir, ".mod")
            shutil.copy(runtime_dir("m2") / "Max2codeRoots.def", folder)
            (folder / "Driver.mod").write_text(self.render(name=unit.name))
            run([gm2, "-fiso", "-fcpp", "-Wall", "-Werror", "-c", module.name,
                 "-o", f"{unit.name}.o"], cwd=folder)
            run([gm2, "-fiso", "Driver.mod", f"{unit.name}.o", str(obj), "-o", "driver",
                 f"-L{iso}", "-lm2iso", "-lpthread", *LIBS], cwd=folder)
            stdin = "".join(" ".join(f"{lo} {hi}" for x in (case.tmax, *case.params)
                                     for lo, hi in [halves(x)]) + " \n" for case in unit.cases)
            out = run([str(folder / "driver")], input=stdin, cwd=folder)
            results[unit.name] = parse_lines(out, len(unit.cases), from_halves)
        return results
