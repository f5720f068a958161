"""bench/roots_kernels.py: its replica of the solver's path must give the public solve's roots
bit for bit (else its table prices a different computation), and its table must have a row per
kernel.  bench/near_window.py: its exact count of certifying pieces and its minima must be
right on polynomials whose answers are known by hand, and its oracle certificate must agree
with the solver.  The timings themselves are not asserted (speed lives in the benchmark's
output, not in tests)."""

from __future__ import annotations

import importlib.util
import re
import subprocess
import sys
from pathlib import Path

import numpy
import pytest

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
    # the paths: every polynomial on one, the certified guesses the ones the kernels priced
    paths = re.findall(r"^\| ([^|]+?) \| (\d+) \| ([\d.]+) \| ([\d.]+) \| (\d+) % \|$", text, re.M)
    assert [p[0].split(" (")[0] for p in paths] == [
        "settled before the guess", "the certified guess",
        "the guess converges, its certificate fails", "the guess fails"], text
    counts = {p[0].split(" (")[0]: int(p[1]) for p in paths}
    assert sum(counts.values()) == total and counts["the certified guess"] == kept, text
    assert counts["the guess fails"] > 0, text  # generic octics: complex roots in the way
    assert all(float(p[2]) > 0 for p in paths if int(p[1]) > 0), text
    mean = float(re.search(r"([\d.]+) evaluations a solve in the mean", text).group(1))
    assert abs(sum(float(p[3]) for p in paths) - mean) <= 0.05 * len(paths), text


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
    for header in ("timing.h", "solve_steps.h"):
        (bench / header).write_text((ROOT / "bench" / header).read_text())
    script = bench / "roots_kernels.py"
    # the copy builds the .c beside it; the runtime and the polynomial families: the checkout's
    code = SCRIPT.read_text()
    assert code.count("ROOT = HERE.parent\n") == 1, "the script's paths changed: adapt the test"
    script.write_text(code.replace("ROOT = HERE.parent\n", f"ROOT = Path({str(ROOT)!r})\n"))
    r = _run(script, "--regions", "3", "-o", str(tmp_path / "out"))
    assert r.returncode != 0
    assert "the replica of the solver's path is off: differ" in r.stderr, r.stderr
    assert not (tmp_path / "out").exists()


NEAR = ROOT / "bench" / "near_window.py"
NEAR_ROWS = ("the runtime's solve today (m2c_first_root_ex)",
             "before any test of the window: validation, the preparation, the tests at 0",
             "those, and the Bernstein test on the whole window",
             "those, and the splits at the minima, given for free (the oracle certificate)",
             "the certificate alone, from prepared coefficients: the point 0, the whole-window "
             "test, the splits")


def _near_module():
    """bench/near_window.py as a module (it puts bench/ on sys.path, as a script does): sys.path
    as it was afterwards."""
    saved = list(sys.path)
    try:
        spec = importlib.util.spec_from_file_location("near_window_under_test", NEAR)
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
    finally:
        sys.path[:] = saved
    return module


def test_fewest_pieces_by_hand() -> None:
    """(t - 1/2)^2 + e^2 on [0, 1]: the Bernstein coefficients are 1/4 + e^2, e^2 - 1/4,
    1/4 + e^2 (one negative), and on [0, 1/2] and [1/2, 1] 1/4 + e^2, e^2, e^2 (mirrored): two
    pieces, as few as there can be.  Without the dip one piece; with a root, no certificate."""
    nw = _near_module()
    e2 = 2.0 ** -20
    assert nw.fewest_pieces((0.25 + e2, -1.0, 1.0), 1.0) == (2, 2)
    assert nw.fewest_pieces((1.0, 0.5, 0.25), 1.0) == (1, 1)
    with pytest.raises(ValueError):
        nw.fewest_pieces((0.25 - e2, -1.0, 1.0), 1.0)  # roots at 1/2 -+ 2^-10


def test_minima_by_hand() -> None:
    """(t - 0.3)^2 (t - 0.7)^2 + 0.01: minima at 0.3 and 0.7, a maximum at 0.5 (not a minimum);
    negated, the same minima of |p|; a window of (0, 0.5) holds only the first."""
    nw = _near_module()
    c = [float(x) for x in numpy.polynomial.polynomial.polyfromroots([0.3, 0.3, 0.7, 0.7])]
    c[0] += 0.01
    got = nw.minima(tuple(c), 1.0)
    assert len(got) == 2 and abs(got[0] - 0.3) < 1e-9 and abs(got[1] - 0.7) < 1e-9, got
    assert nw.minima(tuple(-x for x in c), 1.0) == got
    assert len(nw.minima(tuple(c), 0.5)) == 1


def test_near_window_table_and_oracle(tmp_path: Path) -> None:
    r = _run(NEAR, "--count", "40", "--sweeps", "2", "-o", str(tmp_path))
    assert r.returncode == 0, r.stderr
    text = (tmp_path / "near_window.md").read_text()
    rows = dict(re.findall(r"^\| (.+?) \| -?\d+ \| (-?[\d.]+) \| -?[\d.]+ \|$", text, re.M))
    assert list(rows) == list(NEAR_ROWS), text
    assert all(float(v) > 0 for v in rows.values()), text
    reached, total, kept = map(int, re.search(
        r"^(\d+) of (\d+) windows reach the whole-window test with an even count, (\d+) of them",
        text, re.M).groups())
    assert total == 40 and 0 < kept <= reached <= total, text
    pieces = re.search(r"on (\d+) of 40 windows, else its upper bound\): median (\d+), mean "
                       r"[\d.]+, at least (\d+) ", text)
    assert pieces and int(pieces.group(3)) >= 2, text  # every window of the family dips
    assert int(pieces.group(1)) > 0, text
    assert "python bench/near_window.py --count 40 --sweeps 2" in text


def test_an_oracle_that_clears_everything_is_refused(tmp_path: Path) -> None:
    """An oracle whose pieces always pass would clear every window of this family (none has a
    root) and so agree with the solve; its negative controls -- each window moved to cross 0 at
    its deepest minimum -- must catch it, and the script must stop with its message and write
    nothing."""
    src = (ROOT / "bench" / "near_window.c").read_text()
    marker = "static int piece_clear(const double b[], double err, int n, int *halved)\n{\n"
    assert src.count(marker) == 1, "the oracle changed: adapt the test"
    bench = tmp_path / "bench"
    bench.mkdir()
    (bench / "near_window.c").write_text(src.replace(marker, marker + "    return 1;\n"))
    for header in ("timing.h", "solve_steps.h"):
        (bench / header).write_text((ROOT / "bench" / header).read_text())
    code = NEAR.read_text()
    assert code.count("ROOT = HERE.parent\n") == 1, "the script's paths changed: adapt the test"
    script = bench / "near_window.py"
    script.write_text(code.replace("ROOT = HERE.parent\n", f"ROOT = Path({str(ROOT)!r})\n"))
    r = _run(script, "--count", "40", "--sweeps", "1", "-o", str(tmp_path / "out"))
    assert r.returncode != 0
    assert "the oracle certificate and the solve disagree: differ" in r.stderr, r.stderr
    assert "negative control" in r.stderr, r.stderr
    assert not (tmp_path / "out").exists()
