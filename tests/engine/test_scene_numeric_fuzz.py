"""Numeric-field fuzz of scene files, CI-sized (issue 33): a hostile value (NaN, +-inf,
+-1e308, -0, subnormals, 10^400) in any numeric field of a scene that uses every field is
refused with `file:line:col: error:` or runs to its end with strict JSON, each within its
timeout. `python bench/scene_numeric_fuzz.py` runs every field times every value
(bench/results/scene-numeric-fuzz.md has the counts)."""

from __future__ import annotations

import tempfile
from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from .numeric_fuzz import VALUES, cases, run_case

CASES = cases()


def test_base_scene_runs(engine, tmp_path: Path) -> None:
    """The scene itself, untouched, runs to its end (so a refusal is the value's doing)."""
    outcome = run_case(tmp_path, ("no such field",), "1e308", "json", timeout=120)
    assert outcome.status == "ran", outcome


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(st.sampled_from(CASES))
def test_hostile_number_is_refused_or_runs(engine, case) -> None:
    target, value, fmt = case
    with tempfile.TemporaryDirectory() as folder:
        outcome = run_case(Path(folder), target, value, fmt, timeout=120)
    assert outcome.status in ("refused", "ran"), outcome
    if value in ("nan", "inf", "-inf", "1e308", "-1e308", "1e400", "10^400 int"):
        assert outcome.status == "refused", outcome  # never a finite run of such a number


def test_every_value_is_tried() -> None:
    assert {v for _, v, _ in CASES} == set(VALUES) and len({f for f, _, _ in CASES}) >= 60
