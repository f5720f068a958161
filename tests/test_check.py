"""Cross-language consistency: `max2code check` on every shipped equation, all four languages.

One check builds every language for every shipped equation (one Rust crate with all modules,
Cargo's target folder kept in build/check) and runs each on tests/vectors/<stem>.jsonl, the
oracle's vectors; every language must meet the tolerances of max2code/check.py on every family.
A perturbed expected root must make the check fail (so it can fail), the vector files must be
what tests/vectors/make_vectors.py makes today, and they must cover the families the issue
asks for.

Tools: maxima, gcc, gm2, cargo. Under CI (CI set) a missing tool fails; elsewhere it skips.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT, require

from max2code import check as chk

EQUATIONS = chk.shipped_equations()
LANGS = ["c", "python", "m2", "rust"]
BUILD_DIR = ROOT / "build" / "check"
FAMILIES = {"generic", "no_root", "graze", "cluster", "degree_drop", "near_zero", "scale"}
sys.path.insert(0, str(ROOT / "tests" / "vectors"))


def require_tools() -> None:
    for name in ("maxima", "gcc", "gm2"):
        require(name)
    if shutil.which("cargo") is None and not (Path.home() / ".cargo" / "bin" / "cargo").exists():
        require("cargo")


@pytest.fixture(scope="module")
def report() -> chk.Report:
    require_tools()
    return chk.check(EQUATIONS, langs=LANGS, build_dir=BUILD_DIR)


def test_every_shipped_equation_has_vectors() -> None:
    assert EQUATIONS
    for mxm in EQUATIONS:
        assert chk.default_vectors(mxm).exists(), f"no vectors for {mxm.name}"


@pytest.mark.parametrize("mxm", EQUATIONS, ids=lambda p: p.stem)
def test_vectors_cover_the_families(mxm: Path) -> None:
    lines = [json.loads(x) for x in chk.default_vectors(mxm).read_text().splitlines()]
    head, vectors = lines[0], lines[1:]
    assert head["max2code_vectors"] == 1 and head["equation"] == f"equations/{mxm.name}"
    assert FAMILIES <= {v["family"] for v in vectors}
    assert any(v["graze"] for v in vectors) and any(v["first_root"] is None for v in vectors)
    scales = {v["note"] for v in vectors if v["family"] == "scale"}
    assert {"lengths times 1e-08", "lengths times 1e+08"} <= scales
    near = [float(v["first_root"]) for v in vectors if v["family"] == "near_zero"]
    assert near and all(1e-10 < t < 1e-8 for t in near)
    for v in vectors:  # exact doubles: hex floats or decimal strings that are exact
        for value in v["params"].values():
            chk.parse_double(value)


@pytest.mark.parametrize("mxm", EQUATIONS, ids=lambda p: p.stem)
def test_all_languages_agree_with_the_oracle(report: chk.Report, mxm: Path) -> None:
    assert not report.errors, "\n".join(report.errors)
    rows = [r for r in report.rows if r.equation == mxm.stem]
    assert {r.lang for r in rows} == set(LANGS)
    vectors = chk.load_vectors(chk.default_vectors(mxm), tuple(json.loads(
        chk.default_vectors(mxm).read_text().splitlines()[0])["parameters"]))
    for lang in LANGS:
        mine = [r for r in rows if r.lang == lang]
        assert sum(r.count for r in mine) == len(vectors), lang
        assert {r.family for r in mine} == {v.family for v in vectors}
    failed = [f for f in report.failures if f"/{mxm.stem}.jsonl:" in f]
    assert all(r.failed == 0 for r in rows), "\n".join(failed) + "\n" + report.text()
    for r in rows:
        assert r.coef_err <= chk.TOLERANCES.coef and r.bound_use <= 1.0
        assert r.missed == 0 and r.spurious == 0


def test_the_report_says_so(report: chk.Report) -> None:
    text = report.text()
    assert report.ok, text
    assert text.rstrip().endswith("check: every language met the tolerances")
    assert json.loads(json.dumps(report.json()))["ok"] is True


def test_a_perturbed_root_fails_the_check(report: chk.Report, tmp_path: Path) -> None:
    """Move one expected root by 1e-9 (relative): far beyond its bound, in every language."""
    mxm = ROOT / "equations" / "point-line.mxm"
    lines = chk.default_vectors(mxm).read_text().splitlines()
    index = next(i for i, x in enumerate(lines)
                 if i and json.loads(x)["family"] == "generic" and json.loads(x)["first_root"])
    vector = json.loads(lines[index])
    vector["first_root"] = repr(float(vector["first_root"]) * (1 + 1e-9))
    lines[index] = json.dumps(vector)
    bad = tmp_path / "point-line.jsonl"
    bad.write_text("\n".join(lines) + "\n")
    result = chk.check([mxm], {mxm: bad}, LANGS, BUILD_DIR)
    assert not result.ok
    assert not result.errors
    for lang in LANGS:
        assert any(f.startswith(f"{bad}:{index + 1}: {lang}: generic") for f in result.failures)
        generic = next(r for r in result.rows if r.lang == lang and r.family == "generic")
        assert generic.failed == 1 and generic.bound_use > 1
        assert all(r.failed == 0 for r in result.rows if r.family != "generic")
    assert result.text().rstrip().endswith("check: FAILED")
    # The command says so in its exit status (Python alone: the point is the status).
    proc = subprocess.run([sys.executable, "-m", "max2code", "check", str(mxm), "--vectors",
                           str(bad), "--lang", "python", "--build-dir", str(BUILD_DIR)],
                          cwd=ROOT, capture_output=True, text=True)
    assert proc.returncode == 1, proc.stdout + proc.stderr
    assert "FAILED" in proc.stdout and f"{bad}:{index + 1}: python: generic" in proc.stdout


def test_a_missed_root_and_a_spurious_one_are_counted(tmp_path: Path) -> None:
    require("maxima")
    mxm = ROOT / "equations" / "point-line.mxm"
    lines = chk.default_vectors(mxm).read_text().splitlines()
    out = [lines[0]]
    for x in lines[1:]:
        v = json.loads(x)
        if v["family"] == "no_root" and len(out) == 1:
            v["first_root"] = "1.5"  # the code finds none: missed
            out.append(json.dumps(v))
        elif v["family"] == "cluster" and len(out) == 2:
            v["first_root"] = None  # the code finds one: spurious
            out.append(json.dumps(v))
    bad = tmp_path / "v.jsonl"
    bad.write_text("\n".join(out) + "\n")
    result = chk.check([mxm], {mxm: bad}, ["python"], BUILD_DIR)
    assert not result.ok
    assert {r.family: (r.missed, r.spurious) for r in result.rows} == {
        "no_root": (1, 0), "cluster": (0, 1)}


def test_the_command_passes_on_shipped_vectors() -> None:
    require("maxima")
    proc = subprocess.run([sys.executable, "-m", "max2code", "check", "--lang", "python",
                           "--lang", "c", str(ROOT / "equations" / "circles-accel.mxm"),
                           "--build-dir", str(BUILD_DIR)], cwd=ROOT, capture_output=True,
                          text=True)
    if proc.returncode != 0 and "'gcc' is not installed" in proc.stdout:
        require("gcc")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "check: every language met the tolerances" in proc.stdout


def test_inexact_decimal_parameters_are_refused() -> None:
    assert chk.parse_double("0.75") == 0.75
    assert chk.parse_double("0x1.999999999999ap-4") == 0.1
    with pytest.raises(chk.VectorError):
        chk.parse_double("0.1")


def test_vectors_are_up_to_date() -> None:
    """The committed file is what the generator makes today (deterministic, same oracle)."""
    require("maxima")
    import make_vectors

    mxm = ROOT / "equations" / "point-line.mxm"
    assert make_vectors.text(mxm) == chk.default_vectors(mxm).read_text()
