"""bench/turning_pairs.py, the measurement behind the moving-vertex limit (docs/game-api.md):
it runs, times every size up to the limit, and shows the first sizes past it refused, as
polygons and as compounds of octagons alike."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def test_the_bench_times_up_to_the_limit_and_shows_past_it_refused() -> None:
    out = subprocess.run([sys.executable, "bench/turning_pairs.py"], cwd=ROOT, check=True,
                         capture_output=True, text=True, timeout=600).stdout
    rows = {tuple(cell.strip() for cell in line.strip("|").split("|")[:3]): line.split("|")[4]
            for line in out.splitlines()[2:]}
    for vertices in ("32", "64", "128"):
        assert rows["polygon", vertices, vertices].strip().endswith(" s")
    assert rows["ring of octagons", "16", "128"].strip().endswith(" s")
    for key in (("polygon", "129", "129"), ("ring of octagons", "17", "136")):
        assert "refused: a dynamic or kinematic body has at most 128 vertices" in rows[key]
