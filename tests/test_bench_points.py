"""bench/horner_points.py: its k-point kernels must give the one-point kernel's bits (else its
table prices a different computation), and its table must have a row per kernel.  The timings
themselves are not asserted (speed lives in the benchmark's output, not in tests)."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

from conftest import ROOT, require

SCRIPT = ROOT / "bench" / "horner_points.py"
ROWS = ("p at 1 point (timing.h's horner8: the unit)", "p at 1 point", "p at 2 points",
        "p at 3 points", "p at 4 points", "p at 6 points", "p at 8 points", "p, p' at 1 point",
        "p, p' at 4 points", "p, p', p'' at 1 point", "p, p', p'' at 4 points")


def _run(*args: str) -> subprocess.CompletedProcess:
    require("gcc")
    return subprocess.run([sys.executable, str(SCRIPT), *args], capture_output=True, text=True,
                          cwd=ROOT, timeout=600)


def test_table_has_every_kernel(tmp_path: Path) -> None:
    r = _run("--regions", "5", "-o", str(tmp_path))
    assert r.returncode == 0, r.stderr
    text = (tmp_path / "horner_points.md").read_text()
    rows = dict(re.findall(r"^\| (.+?) \| [\d.]+ \| ([\d.]+) \| [\d.]+ \|$", text, re.M))
    assert list(rows) == list(ROWS), text
    assert rows[ROWS[0]] == "1.00" and all(float(v) > 0 for v in rows.values())
    assert "python bench/horner_points.py --regions 5" in text


def test_a_wrong_kernel_is_refused(tmp_path: Path) -> None:
    """A 4-point kernel whose third point reads its coefficients one step late must be caught
    by the bit-for-bit check, and the script must stop with its message."""
    src = (ROOT / "bench" / "horner_points.c").read_text()
    marker = "                t[0][j] = t[0][j] * x[j] + c[i];                                            \\\n"
    assert src.count(marker) == 1, "the kernels' loop changed: adapt the test"
    wrong = src.replace(marker, "                t[0][j] = t[0][j] * x[j] + c[i + (j == 2 && K == 4 && i < 7)]; \\\n")
    bench = tmp_path / "bench"
    bench.mkdir()
    (bench / "horner_points.c").write_text(wrong)
    for name in ("timing.h", "benchtools.py"):
        (bench / name).write_text((ROOT / "bench" / name).read_text())
    (bench / "horner_points.py").write_text(SCRIPT.read_text())
    r = subprocess.run([sys.executable, str(bench / "horner_points.py"), "--regions", "3", "-o",
                        str(tmp_path / "out")], capture_output=True, text=True, timeout=600)
    assert r.returncode != 0
    assert "the kernels disagree: p at 4 points: polynomial 0 point 2" in r.stderr
    assert not (tmp_path / "out" / "horner_points.md").exists()
