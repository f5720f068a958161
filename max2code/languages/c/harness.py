"""C: the generated header and a driver, gcc -std=c11 -Wall -Wextra -Werror -pedantic, linked with
the C runtime (runtime/c, GSL). Numbers travel as C99 hex floats (%a), exactly."""

from __future__ import annotations

from pathlib import Path

from ...paths import runtime_dir
from ..harness import Harness, Outcome, Unit, parse_lines, run, tool
from .runtime import LIBS

CFLAGS = ["-std=c11", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O2"]


def runtime_object(gcc: str, workdir: Path) -> Path:
    """The C runtime compiled once per run (the Modula-2 harness links it too)."""
    obj = workdir / "max2code_roots.o"
    if not obj.exists():
        source = runtime_dir("c") / "max2code_roots.c"
        run([gcc, *CFLAGS, f"-I{runtime_dir('c')}", "-c", str(source), "-o", str(obj)])
    return obj


class CHarness(Harness):
    lang = "c"
    tools = ("gcc",)

    def run(self, units: list[Unit], workdir: Path, build_dir: Path) -> dict[str, list[Outcome]]:
        gcc = tool("gcc")
        obj = runtime_object(gcc, workdir)
        results = {}
        for unit in units:
            folder, header = self.write_module(unit, workdir, ".h")
            (folder / "driver.c").write_text(self.render(name=unit.name, header=header.name))
            exe = folder / "driver"
            run([gcc, *CFLAGS, f"-I{runtime_dir('c')}", f"-I{folder}", str(folder / "driver.c"),
                 str(obj), "-o", str(exe), *LIBS])
            stdin = "".join(" ".join(float.hex(x) for x in (case.tmax, *case.params)) + "\n"
                            for case in unit.cases)
            out = run([str(exe)], input=stdin)
            results[unit.name] = parse_lines(out, len(unit.cases), float.fromhex)
        return results
