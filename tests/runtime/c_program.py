"""Build and run a test program that includes the C runtime's source (its kernels are static):
the tests that check a kernel against its definition print "N differences" and fail on any."""
from __future__ import annotations

import subprocess
from pathlib import Path

from conftest import require

C_DIR = Path(__file__).resolve().parents[2] / "runtime" / "c"


def run_c_program(program: str, tmp_path: Path, name: str, stdin: str = "") -> str:
    """Compiles `program` (gcc -O2, no GSL, the runtime's folder on the include path), runs it
    on `stdin`, and returns what it printed, asserting that it ran to the end with no
    difference."""
    gcc = require("gcc")
    src = tmp_path / f"{name}.c"
    src.write_text(program)
    exe = tmp_path / name
    r = subprocess.run([gcc, "-O2", "-std=c11", "-DM2C_NO_GSL", "-I", str(C_DIR), str(src), "-o",
                        str(exe), "-lm"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    run = subprocess.run([str(exe)], input=stdin, capture_output=True, text=True, timeout=300)
    last = run.stdout.strip().split("\n")[-1].split()
    assert run.returncode == 0 and last[-2:] == ["0", "differences"], run.stdout
    return run.stdout
