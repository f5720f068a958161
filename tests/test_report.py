"""`max2code report` and `max2code roles`: the numbers they print come from the real pipeline."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from conftest import ROOT

from max2code.roles import suggest


def test_report_files_and_figure6(tmp_path: Path, maxima_exe: str) -> None:
    result = subprocess.run([sys.executable, "-m", "max2code", "report", "-o", str(tmp_path),
                             "equations/circles-orbit.mxm"], cwd=ROOT, capture_output=True,
                            text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    data = json.loads((tmp_path / "report.json").read_text())
    (eq,) = data["equations"]
    assert eq["source"] == "equations/circles-orbit.mxm" and eq["degree"] == 8
    general = {s: eq["variants"][s][-1] for s in ("optimised", "expanded")}
    assert general["optimised"]["label"] == "general"
    total = {s: g["add"] + g["mul"] + g["div"] for s, g in general.items()}
    assert total["expanded"] >= 5 * total["optimised"]
    assert set(eq["lines"]["optimised"]) == {"c", "m2", "python", "rust"}
    rows = {r["label"]: r for r in data["figure6"]}
    paper = rows["Two circles (paper's figures 5+7, verbatim)"]
    assert paper["paper"] == [33, 835, 977]
    assert paper["mxm_lines"] == (ROOT / "equations/paper/circle-circle.mxm").read_text().count("\n")
    assert "<svg" in (tmp_path / "report.html").read_text()
    assert "## The paper's figure 6, reproduced" in (tmp_path / "report.md").read_text()


def test_roles_suggests_what_lowers_the_degree(maxima_exe: str) -> None:
    rows = suggest("equations/circles-orbit.mxm", 120.0)
    (_, degree, ops), rest = rows[0], rows[1:]
    assert degree == 8
    by_zeros = {z: (d, o) for z, d, o in rest}
    assert by_zeros[("w1", "w2")][0] == 4  # no rotation at all: the quartic
    assert all(d < degree or o <= 0.9 * ops for d, o in by_zeros.values())
