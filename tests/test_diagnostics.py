"""Warnings and notes, verbatim: tests/bad/NAME.stderr is the whole standard error of a run
that succeeds (exit 0) on tests/bad/NAME.mxm, whose first line names the command
(`// max2code --lang=c`). Errors are in tests/bad/NAME.expected (tests/test_bad_input.py).

Paths are as seen from the repository root; output goes to a temporary file."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT

BAD = ROOT / "tests" / "bad"
NAMES = sorted(p.stem for p in BAD.glob("*.stderr"))


def test_there_are_cases() -> None:
    assert {"renamed-parameters-module", "renamed-parameter-fragment", "role-without-variant",
            "role-same-as-another"} <= set(NAMES)


@pytest.mark.parametrize("name", NAMES)
def test_diagnostics_verbatim(name: str, tmp_path: Path, maxima_exe: str) -> None:
    mxm = BAD / f"{name}.mxm"
    first = mxm.read_text().splitlines()[0]
    assert first.startswith("// max2code "), "the first line names the command"
    args = first.removeprefix("// max2code ").split()
    proc = subprocess.run([sys.executable, "-m", "max2code", *args, f"tests/bad/{name}.mxm",
                           "-o", str(tmp_path / "out")], cwd=ROOT, capture_output=True,
                          text=True, timeout=300,
                          env={**os.environ, "MAX2CODE_CACHE": str(tmp_path / "cache")})
    assert proc.returncode == 0, proc.stderr
    assert proc.stderr == (BAD / f"{name}.stderr").read_text(encoding="utf-8")
    assert (tmp_path / "out").exists()
