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
    degree, ops, candidates = suggest("equations/circles-orbit.mxm", 120.0)
    assert degree == 8
    by_zeros = {c.zeros: c for c in candidates}
    assert by_zeros[("w1", "w2")].degree == 4  # no rotation at all: the quartic
    assert by_zeros[("w1", "w2")].kind == "effect" and by_zeros[("ox1", "oy1")].kind == "vector"
    for c in candidates:
        if c.useful:
            assert c.degree < degree or (c.ops <= 0.9 * ops and c.ops <= ops - 3)
    assert ("vx1",) in by_zeros and not by_zeros[("vx1",)].useful


SPHERES = """\
// two accelerating spheres in 3D
function spheres
begin
X: x1 + vx1*t + ax1*t^2/2 - (x2 + vx2*t + ax2*t^2/2);
Y: y1 + vy1*t + ay1*t^2/2 - (y2 + vy2*t + ay2*t^2/2);
Z: z1 + vz1*t + az1*t^2/2 - (z2 + vz2*t + az2*t^2/2);
X^2 + Y^2 + Z^2 - (r1 + r2)^2;
end
"""


def test_roles_finds_vectors_by_name_and_effect(tmp_path: Path, maxima_exe: str) -> None:
    """3D: a vector's three components by name, both bodies' accelerations by their equal effect
    (together they lower the degree); the command prints only what is worth a role."""
    mxm = tmp_path / "spheres.mxm"
    mxm.write_text(SPHERES)
    proc = subprocess.run([sys.executable, "-m", "max2code", "roles", str(mxm)], cwd=ROOT,
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.splitlines()
    assert lines[0] == f"{mxm}: general polynomial of degree 4, 58 operations (optimised)"
    suggested = [line.split("=")[1].split(" degree")[0].strip() for line in lines[1:]]
    assert suggested == ["ax1, ay1, az1, ax2, ay2, az2", "ax1, ay1, az1", "ax2, ay2, az2"]
    assert "degree 2, 27 operations (-31; effect)" in lines[1]
    everything = subprocess.run([sys.executable, "-m", "max2code", "roles", "--all", str(mxm)],
                                cwd=ROOT, capture_output=True, text=True, timeout=600).stdout
    assert "role vx1 = vx1" in everything and "not worth a role" in everything
