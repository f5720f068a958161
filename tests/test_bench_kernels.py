"""bench/roots_kernels.py: its replica of the solver's path must give the public solve's roots
bit for bit (else its table prices a different computation), and its table must have a row per
kernel.  The timings themselves are not asserted (speed lives in the benchmark's output, not in
tests)."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

from conftest import ROOT, require

SCRIPT = ROOT / "bench" / "roots_kernels.py"
ROWS = ("the whole solve (m2c_first_root_ex)",
        "before the guess: validation, the preparation, the tests at 0 (a replica of solve's steps)",
        "the guess: Laguerre from 0 (speculate_first_root)",
        "its certificate: Bernstein test on (0, r (1 + 2^-20)] (bernstein_test)",
        "the polish: p', then compensated Newton (derivative, refine_root)",
        "the rest: calls, copies, and what the kernels cost more inside one solve than each on its own")


def _run(script: Path, *args: str) -> subprocess.CompletedProcess:
    require("gcc")
    return subprocess.run([sys.executable, str(script), *args], capture_output=True, text=True,
                          cwd=ROOT, timeout=600)


def test_table_has_every_kernel(tmp_path: Path) -> None:
    r = _run(SCRIPT, "--regions", "3", "--count", "100", "-o", str(tmp_path))
    assert r.returncode == 0, r.stderr
    text = (tmp_path / "roots_kernels_generic8.md").read_text()
    rows = dict(re.findall(r"^\| (.+?) \| -?\d+ \| (-?[\d.]+) \| -?\d+ % \|$", text, re.M))
    assert list(rows) == list(ROWS), text
    assert all(float(v) > 0 for k, v in rows.items() if not k.startswith("the rest")), text
    kept, total = map(int, re.search(r"^(\d+) of (\d+) polynomials settled", text, re.M).groups())
    assert total == 100 and 0 < kept < total
    assert "python bench/roots_kernels.py --count 100 --regions 3" in text


def test_a_replica_off_the_solver_path_is_refused(tmp_path: Path) -> None:
    """A replica that keeps the guesses whose certificate fails (some of them converged to a
    later root, or none) must be caught by the bit-for-bit check, and the script must stop with
    its message and write nothing."""
    src = (ROOT / "bench" / "roots_kernels.c").read_text()
    marker = "    if (bernstein_test(&k->a, n, w, &pT, NULL) != BERN_ONE)\n"
    assert src.count(marker) == 1, "the replica changed: adapt the test"
    bench = tmp_path / "bench"
    bench.mkdir()
    (bench / "roots_kernels.c").write_text(src.replace(marker, marker.replace("if (", "if (0 && ")))
    (bench / "timing.h").write_text((ROOT / "bench" / "timing.h").read_text())
    script = bench / "roots_kernels.py"
    # the copy builds the .c beside it; the runtime and the polynomial families: the checkout's
    code = SCRIPT.read_text()
    assert code.count("ROOT = HERE.parent\n") == 1, "the script's paths changed: adapt the test"
    script.write_text(code.replace("ROOT = HERE.parent\n", f"ROOT = Path({str(ROOT)!r})\n"))
    r = _run(script, "--regions", "3", "-o", str(tmp_path / "out"))
    assert r.returncode != 0
    assert "the replica of the solver's path is off: differ" in r.stderr, r.stderr
    assert not (tmp_path / "out").exists()
