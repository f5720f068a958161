"""CI draws the same property-test examples each run, a developer's run new ones.

`make test` (what CI runs) sets CI=true, and hypothesis then loads its built-in "ci" profile:
derandomized, no example database. A red CI run is then the code's, and repeats; a bare
`pytest` draws new examples each run and keeps the failures it finds in .hypothesis/. Every
property test that relies on this (no explicit `derandomize`) would flicker in CI without it.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from hypothesis import _settings as hypothesis_settings
from hypothesis import settings

ROOT = Path(__file__).resolve().parents[1]

PROBE = '''
from hypothesis import given, settings, strategies as st
seen = []
@given(st.integers())
def test_draw(x):
    seen.append(x)
def test_zz_report():
    print("DRAWN", sum(hash(x) for x in seen), settings.default.derandomize)
'''


def draws(tmp_path: Path, ci: bool) -> str:
    """One pytest run of PROBE (this venv's hypothesis), in CI or not; what it drew."""
    env = {k: v for k, v in os.environ.items() if k not in hypothesis_settings._CI_VARS}
    if ci:
        env["CI"] = "true"
    probe = tmp_path / "test_probe.py"
    probe.write_text(PROBE)
    out = subprocess.run([sys.executable, "-m", "pytest", "-q", "-s", "-p", "no:cacheprovider",
                          str(probe)], capture_output=True, text=True, timeout=300,
                         cwd=tmp_path, env=env).stdout
    line = next(line for line in out.splitlines() if "DRAWN" in line)   # (after pytest's dot)
    return line[line.index("DRAWN"):]


def test_ci_draws_the_same_examples_each_run_and_a_bare_run_new_ones(tmp_path):
    ci = [draws(tmp_path, ci=True) for _ in range(2)]
    assert ci[0] == ci[1] and ci[0].endswith("True")
    bare = [draws(tmp_path, ci=False) for _ in range(2)]
    assert bare[0] != bare[1] and bare[0].endswith("False")


def test_make_test_runs_in_ci_mode_and_nothing_here_undoes_it():
    assert "CI=true $(PYTHON) -m pytest" in (ROOT / "Makefile").read_text()
    if os.environ.get("CI"):   # (this run's own profile: no conftest loaded another)
        assert settings.default.derandomize and settings.default.database is None
