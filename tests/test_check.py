"""Cross-language consistency: `max2code check` on every shipped equation, all four languages.

One check builds every language for every shipped equation (one Rust crate with all modules,
Cargo's target folder kept in build/check) and runs each on tests/vectors/<stem>.jsonl, the
oracle's vectors; every language must meet the tolerances of max2code/commands/check.py on every family.
A perturbed expected root must make the check fail (so it can fail), the vector files must be
what tests/vectors/make_vectors.py makes today, and they must cover the families the issue
asks for.

Tools: maxima, gcc, gm2, cargo. Under CI (CI set) a missing tool fails; elsewhere it skips.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import pytest

from conftest import ROOT, require

from max2code.commands import check as chk

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


def test_an_equation_with_decimal_constants(tmp_path: Path) -> None:
    """x + v t + 0.5 a t^2 (a reviewer's case): Maxima leaves the remainder of the polynomial's
    terms as 0.0 where the equation has decimals, which was read as "not a polynomial"; every
    language now builds it and meets the oracle (Maxima in bigfloat) on fresh vectors."""
    require("maxima")
    mxm = tmp_path / "decimals.mxm"
    mxm.write_text("parameters x, v, a\nbegin\n  x + v*t + 0.5*a*t^2 - 1.25;\nend\n")
    proc = subprocess.run([sys.executable, "-m", "max2code", "check", str(mxm), "--build-dir",
                           str(tmp_path / "build")], cwd=tmp_path, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "check: every language met the tolerances" in proc.stdout
    for lang in ("c", "python", "rust", "m2"):
        assert f"decimals           {lang}" in proc.stdout, proc.stdout


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


# ---------------------------------------------------------------------------------------------
# A user's own equations: `max2code vectors`, and check making its vectors
# ---------------------------------------------------------------------------------------------

QUADRATIC = "// a user's equation\nfunction quad\nbegin\na*t^2 - b*t + c;\nend\n"
PGE = next((p for p in (ROOT.parent / "shared" / "corpus" / "pge",
                        ROOT.parent.parent / "shared" / "corpus" / "pge") if p.is_dir()), None)


def max2code(*args: str, cwd: Path = ROOT, env: dict | None = None) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "max2code", *args], cwd=cwd, capture_output=True,
                          text=True, timeout=1200, env=env)


def test_vectors_command(tmp_path: Path, maxima_exe: str) -> None:
    """The vectors of a*t^2 - b*t + c, checked here without the oracle: the coefficients are the
    parameters themselves, and the first root is the quadratic's (mpmath, 50 digits)."""
    import mpmath

    mxm = tmp_path / "quad.mxm"
    mxm.write_text(QUADRATIC)
    out = tmp_path / "quad.jsonl"
    proc = max2code("vectors", str(mxm), "-o", str(out))
    assert proc.returncode == 0, proc.stderr
    first = out.read_text()
    assert max2code("vectors", str(mxm)).stdout == first  # deterministic; stdout by default
    head, *lines = [json.loads(x) for x in first.splitlines()]
    assert head["max2code_vectors"] == 1 and head["parameters"] == ["a", "b", "c"]
    assert {x["family"] for x in lines} == {"generic", "no_root"}
    assert sum(x["family"] == "generic" for x in lines) == 16
    mpmath.mp.dps = 50
    for x in lines:
        a, b, c = (Fraction(chk.parse_double(x["params"][n])) for n in "abc")
        assert [Fraction(v) for v in x["coefficients"]] == [c, -b, a]
        exact = [mpmath.mpf(v.numerator) / v.denominator for v in (a, -b, c)]
        roots = [r for r in mpmath.polyroots(exact, extraprec=100)
                 if abs(mpmath.im(r)) < 1e-40 and 0 < mpmath.re(r) <= x["tmax"]]
        want = min(mpmath.re(r) for r in roots) if roots else None
        if want is None:
            assert x["first_root"] is None
        else:
            assert abs(mpmath.mpf(x["first_root"]) - want) <= mpmath.mpf(10) ** -28 * want
    assert any(x["first_root"] for x in lines) and any(x["first_root"] is None for x in lines)


def test_check_makes_vectors_for_a_users_equation(tmp_path: Path) -> None:
    """The issue's reproducer: check FILE.mxm on an equation of one's own, all four languages;
    the vectors are made once and then served from the cache, keyed by the .mxm's content."""
    require_tools()
    mxm = tmp_path / "quad.mxm"
    mxm.write_text(QUADRATIC)
    env = {**os.environ, "MAX2CODE_CACHE": str(tmp_path / "cache")}
    args = ("check", str(mxm), "--build-dir", str(BUILD_DIR))
    first = max2code(*args, cwd=tmp_path, env=env)
    assert first.returncode == 0, first.stdout + first.stderr
    assert "(made by the oracle)" in first.stdout
    assert first.stdout.rstrip().endswith("check: every language met the tolerances")
    for lang in LANGS:
        assert f"quad               {lang:<7} generic       16" in first.stdout
    again = max2code(*args, cwd=tmp_path, env=env)
    assert again.returncode == 0 and "(the oracle's, cached)" in again.stdout
    mxm.write_text(QUADRATIC.replace("a*t^2", "2*a*t^2"))
    changed = max2code(*args, cwd=tmp_path, env=env)
    assert changed.returncode == 0 and "(made by the oracle)" in changed.stdout
    assert len(list((tmp_path / "cache" / "vectors").glob("*.jsonl"))) == 2


def test_no_harness_for_an_empty_vector_set(tmp_path: Path, maxima_exe: str) -> None:
    mxm = tmp_path / "quad.mxm"
    mxm.write_text(QUADRATIC)
    empty = tmp_path / "empty.jsonl"
    empty.write_text(json.dumps({"max2code_vectors": 1, "parameters": ["a", "b", "c"]}) + "\n")
    result = chk.check([mxm], {mxm: empty}, LANGS, tmp_path / "build")
    assert not result.ok and result.rows == []
    assert result.errors == [f"{mxm}: {empty}: no vectors (nothing to check; no module built)"]
    assert not (tmp_path / "build" / "cargo-target").exists()  # nothing was built


def test_the_oracle_needs_mpmath_and_says_so(tmp_path: Path, maxima_exe: str) -> None:
    fake = tmp_path / "fake"
    fake.mkdir()
    (fake / "mpmath.py").write_text("raise ImportError('no mpmath here')\n")
    mxm = tmp_path / "quad.mxm"
    mxm.write_text(QUADRATIC)
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(fake), str(ROOT)])}
    proc = max2code("vectors", str(mxm), env=env)
    assert proc.returncode == 1
    assert proc.stderr == ("max2code:1:1: error: the oracle needs mpmath: pip install "
                           "'max2code[oracle]' (or pip install mpmath)\n")


@pytest.mark.skipif(PGE is None, reason="the original PGE corpus (../shared/corpus/pge) is not here")
def test_the_original_pge_files_pass_check(tmp_path: Path) -> None:
    """Every .mxm of the original project, nobody here wrote them: generated as modules in all
    four languages, built, and held to the oracle's vectors."""
    require_tools()
    assert PGE is not None
    files = sorted(PGE.glob("*.mxm"))
    assert len(files) == 6
    result = chk.check(files, langs=LANGS, build_dir=BUILD_DIR)
    assert result.ok, result.text()
    assert {(r.equation, r.lang) for r in result.rows} == {
        (f.stem, lang) for f in files for lang in LANGS}


def test_no_parameters_and_a_variant_that_reads_none(tmp_path: Path) -> None:
    """Edge cases of a user's equation: no parameters at all (C and Modula-2 have no empty
    arrays), and a variant whose coefficients read no parameter (gm2 -Wall: unused `p`)."""
    require_tools()
    nop = tmp_path / "nop.mxm"
    nop.write_text("function nop\nbegin\nt^2 - 2*t - 3;\nend\n")
    novar = tmp_path / "novar.mxm"
    novar.write_text("function novar\nparameters a\nrole still = a\nbegin\nt^2 - 1 + a*t^3;\nend\n")
    result = chk.check([nop, novar], langs=LANGS, build_dir=BUILD_DIR)
    assert result.ok, result.text()
    assert {(r.equation, r.family) for r in result.rows if r.lang == "m2"} >= {
        ("nop", "generic"), ("novar", "variant")}
