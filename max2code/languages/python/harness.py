"""Python: the generated module imported by a driver run under this interpreter, with
runtime/python on sys.path. Numbers travel as hex floats (float.hex), exactly."""

from __future__ import annotations

import sys
from pathlib import Path

from ...paths import runtime_dir
from ..harness import Harness, Outcome, Unit, parse_lines, run


class PythonHarness(Harness):
    lang = "python"
    tools = ()

    def run(self, units: list[Unit], workdir: Path, build_dir: Path) -> dict[str, list[Outcome]]:
        results = {}
        for unit in units:
            folder, _ = self.write_module(unit, workdir, ".py")
            driver = folder / "driver.py"
            driver.write_text(self.render(module=unit.name, paths=[str(runtime_dir("python")),
                                                                   str(folder)]))
            stdin = "".join(" ".join(float.hex(x) for x in (case.tmax, *case.params)) + "\n"
                            for case in unit.cases)
            out = run([sys.executable, "-I", str(driver)], input=stdin, cwd=folder)
            results[unit.name] = parse_lines(out, len(unit.cases), float.fromhex)
        return results
