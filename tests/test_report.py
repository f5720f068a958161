"""`max2code report` and `max2code roles`: the numbers they print come from the real pipeline,
and the HTML page renders in a real browser (headless Chromium from Debian's packages) without
console errors, with its heading, tables and charts."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from html.parser import HTMLParser
from pathlib import Path

import pytest

from conftest import ROOT, require

from max2code.commands.roles import suggest


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


class Page(HTMLParser):
    """What a rendered page holds: headings, tables (their header cells and row counts), charts
    (their bars), and any reference to another file."""

    def __init__(self) -> None:
        super().__init__()
        self.headings: list[tuple[str, str]] = []
        self.tables: list[dict] = []
        self.charts: list[int] = []       # bars per chart
        self.missing: list[int] = []      # 'no variant' marks per chart
        self.external: list[str] = []
        self._heading: str | None = None
        self._cell: str | None = None

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        values = dict(attrs)
        if tag in ("h1", "h2", "h3"):
            self._heading, self.text = tag, ""
        elif tag == "table":
            self.tables.append({"th": [], "rows": 0})
        elif tag == "th":
            self._cell, self.text = "th", ""
        elif tag == "tr" and self.tables:
            self.tables[-1]["rows"] += 1
        elif tag == "svg":
            self.charts.append(0)
            self.missing.append(0)
        elif tag == "rect" and self.charts:
            if values.get("class") == "missing":
                self.missing[-1] += 1
            else:
                self.charts[-1] += 1
        for name in ("src", "href"):
            if values.get(name):
                self.external.append(str(values[name]))

    def handle_data(self, data: str) -> None:
        if self._heading or self._cell:
            self.text += data

    def handle_endtag(self, tag: str) -> None:
        if tag == self._heading:
            self.headings.append((tag, self.text.strip()))
            self._heading = None
        elif tag == "th" and self._cell:
            self.tables[-1]["th"].append(self.text.strip())
            self._cell = None


def chromium(page: Path, tmp_path: Path, *args: str) -> tuple[str, list[str]]:
    """Run headless Chromium on a page: (its standard output, the console messages logged)."""
    exe = shutil.which("chromium") or require("chromium")
    profile = tmp_path / f"profile-{len(list(tmp_path.glob('profile-*')))}"
    proc = subprocess.run(
        [exe, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run",
         f"--user-data-dir={profile}", "--enable-logging=stderr", "--v=0", *args,
         page.resolve().as_uri()], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr[-2000:]
    console = [line for line in proc.stderr.splitlines() if ":CONSOLE" in line]
    return proc.stdout, console


def test_the_console_check_can_fail(tmp_path: Path) -> None:
    page = tmp_path / "bad.html"
    page.write_text('<!doctype html><html lang="en"><title>x</title><p>x</p>'
                    '<script>console.error("boom"); undefinedFunction();</script></html>')
    _, console = chromium(page, tmp_path, "--dump-dom")
    assert any('"boom"' in line for line in console)
    assert any("undefinedFunction is not defined" in line for line in console)


@pytest.fixture(scope="module")
def shipped_report(tmp_path_factory: pytest.TempPathFactory, maxima_exe: str) -> Path:
    out = tmp_path_factory.mktemp("report")
    proc = subprocess.run([sys.executable, "-m", "max2code", "report", "-o", str(out),
                           *map(str, sorted((ROOT / "equations").glob("*.mxm")))], cwd=ROOT,
                          capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, proc.stderr
    return out


def test_the_html_report_renders(shipped_report: Path, tmp_path: Path) -> None:
    page = shipped_report / "report.html"
    dom, console = chromium(page, tmp_path, "--dump-dom")
    assert console == []
    parsed = Page()
    parsed.feed(dom)
    equations = json.loads((shipped_report / "report.json").read_text())["equations"]
    assert parsed.headings[0] == ("h1", "max2code variant report")
    assert ("h2", "The paper's figure 6, reproduced") in parsed.headings
    assert [h for h in parsed.headings if h[0] == "h2"][1:] == [
        ("h2", e["source"]) for e in equations]
    # Per equation: the optimised and expanded variant tables and the lines table; plus fig. 6.
    assert len(parsed.tables) == 1 + 3 * len(equations)
    assert parsed.tables[0]["th"][0] == "expression" and parsed.tables[0]["rows"] == 1 + 4
    for k, e in enumerate(equations):
        opt, exp, lines = parsed.tables[1 + 3 * k: 4 + 3 * k]
        assert opt["th"] == ["#", "variant", "zero parameters", "degree", "add", "mul", "div",
                             "total"]
        assert opt["rows"] == 1 + len(e["variants"]["optimised"])
        assert exp["rows"] == 1 + len(e["variants"]["expanded"])
        assert lines["th"] == ["strategy", "c", "m2", "python", "rust"]
    # One chart per equation, a bar per variant and strategy.
    assert parsed.charts == [len(e["variants"]["optimised"]) + len(e["variants"]["expanded"])
                             for e in equations]
    # and a 'no variant' mark where one strategy has a variant the other has not
    assert parsed.missing == [
        len({v["label"] for v in e["variants"]["optimised"]} ^ {v["label"] for v in e["variants"]["expanded"]})
        for e in equations]
    assert parsed.external == []  # self-contained: nothing to fail to load
    shot = tmp_path / "report.png"
    chromium(page, tmp_path, "--window-size=1200,3000", f"--screenshot={shot}")
    data = shot.read_bytes()
    assert data.startswith(b"\x89PNG") and len(data) > 50_000  # a blank page is a few KB


def test_figure6_only_for_shipped_equations_or_on_request(tmp_path: Path,
                                                          maxima_exe: str) -> None:
    mine = tmp_path / "mine.mxm"
    mine.write_text("function mine\nbegin\n(x + v*t)^2 - r^2;\nend\n")

    def report(*args: str) -> dict:
        out = tmp_path / f"out{len(list(tmp_path.glob('out*')))}"
        proc = subprocess.run([sys.executable, "-m", "max2code", "report", "-o", str(out), *args],
                              cwd=tmp_path, capture_output=True, text=True, timeout=600)
        assert proc.returncode == 0, proc.stderr
        html = (out / "report.html").read_text()
        assert ("figure 6" in html) == bool(json.loads((out / "report.json").read_text())["figure6"])
        return json.loads((out / "report.json").read_text())

    assert report()["figure6"] == []  # the folder's own .mxm, no paper figure
    assert report(str(mine))["figure6"] == []
    assert len(report(str(mine), "--figure6")["figure6"]) == 4
    shipped = str(ROOT / "equations" / "point-line.mxm")
    assert len(report(shipped)["figure6"]) == 4
    assert report(shipped, "--no-figure6")["figure6"] == []


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


def test_the_report_is_the_same_bytes_every_run(tmp_path: Path, maxima_exe: str) -> None:
    """Variants with the same count of operations were charted in a set's order, which Python's
    string hashing changes from run to run: an unchanged report must be the same file (build
    systems compare it), so ties go by label."""
    outs = []
    for seed in ("1", "2", "3"):
        out = tmp_path / seed
        r = subprocess.run([sys.executable, "-m", "max2code", "report", "-o", str(out),
                            "equations/circle-orbit-line.mxm"], cwd=ROOT, capture_output=True,
                           text=True, env={**__import__("os").environ, "PYTHONHASHSEED": seed})
        assert r.returncode == 0, r.stderr
        outs.append((out / "report.html").read_bytes())
    assert outs[0] == outs[1] == outs[2]


def test_long_variant_labels_fit_the_chart(tmp_path: Path, maxima_exe: str) -> None:
    """Labels are right-aligned before the bars; the column now grows with the longest label
    (role names of 40 characters were cut off at the chart's left edge)."""
    import re

    mxm = tmp_path / "long.mxm"
    mxm.write_text("parameters ax, bx, cx, dx\n"
                   "role nothing_accelerates_anywhere_in_this_scene = ax\n"
                   "role the_second_thing_is_at_rest_all_the_time = bx\n"
                   "begin\n  dx + cx*t + ax*t^2 + bx*t^3;\nend\n")
    r = subprocess.run([sys.executable, "-m", "max2code", "report", "-o", str(tmp_path / "r"),
                        str(mxm)], cwd=ROOT, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    page = (tmp_path / "r" / "report.html").read_text()
    labels = re.findall(r'<text x="([\d.]+)" y="[\d.]+" font-size="13" text-anchor="end">([^<]+)</text>', page)
    assert labels and any(len(text) > 60 for _, text in labels)
    for x, text in labels:  # about 7.4 px a character at 13 px: room left of the anchor
        assert float(x) >= 7.4 * len(text.replace("&amp;", "&")), (x, text)


def test_markdown_outputs_hold_paths_as_text(tmp_path: Path, maxima_exe: str) -> None:
    """A file name is data: in summary.md and report.md a '|' must not add a column, a newline
    must not start a heading, '<...>' must not be HTML, '[...]' no link (a reviewer's
    `a|b.mxm` and a name with a newline and an <img onerror>)."""
    import re

    src = tmp_path / "src"
    src.mkdir()
    text = (ROOT / "equations" / "point-line.mxm").read_text()
    names = ["a|b.mxm", "x\n# injected <img src=x onerror=alert(1)> [l](javascript:1).mxm"]
    for name in names:
        (src / name).write_text(text.replace("function point_line", "")
                                if "function" in text else text)
    for cmd in (["build", "-o", str(tmp_path / "b"), "--lang", "c"], ["report", "-o", str(tmp_path / "r")]):
        r = subprocess.run([sys.executable, "-m", "max2code", *cmd, *sorted(str(src / n) for n in names)],
                           cwd=ROOT, capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
    for md in (tmp_path / "b" / "summary.md", tmp_path / "r" / "report.md"):
        out = md.read_text()
        assert "<img" not in out and "\n# injected" not in out, out
        assert not re.search(r"(?<!\\)\]\(", out), out  # no link: its ']' is escaped
        header = next(line for line in out.splitlines() if line.startswith("| "))
        for line in out.splitlines():  # every row of a table has its header's columns
            if line.startswith("| ") and "b.mxm" in line:
                unescaped = len(re.findall(r"(?<!\\)\|", line))
                assert unescaped == header.count("|") or "report" in str(md), (line, header)
        assert "a\\|b.mxm" in out


def _equation(expanded: list[tuple[str, int, int]], optimised: list[tuple[str, int, int]]):
    """An EquationReport from (label, degree, operations) rows, no Maxima needed."""
    from max2code.commands.report import EquationReport, VariantRow
    rows = lambda vs: [VariantRow(i, l, [], d, ops, 0, 0) for i, (l, d, ops) in enumerate(vs)]  # noqa: E731
    return EquationReport("eq.mxm", 4, ["a"], 0.5, {"expanded": rows(expanded),
                                                    "optimised": rows(optimised)}, {})


def test_the_chart_marks_a_missing_variant_and_shows_degrees() -> None:
    """A strategy without a variant left an empty place that read as zero operations: now a
    hatched 'no variant' mark; each row names its degree; every text is 13 px or more; the
    chart has a title, the machine and the date."""
    import re

    from max2code.commands.report import chart

    eq = _equation([("general", 4, 90), ("no flat", 3, 40), ("only expanded", 2, 12)],
                   [("general", 4, 50), ("no flat", 3, 20), ("only optimised", 1, 7)])
    svg = chart(eq, made="Test CPU, 2 cores, 2026-01-02")
    missing = re.findall(r'<rect class="missing"[^>]*><title>([^<]+)</title>', svg)
    assert missing == ["only expanded: no optimised variant", "only optimised: no expanded variant"]
    bars = re.findall(r'<rect class="(expanded|optimised)"[^>]*width="([\d.]+)"', svg)
    assert len(bars) == 6 and all(float(w) > 0 for _, w in bars)
    degrees = re.findall(r'<text class="degree"[^>]*>degree ([\d/]+)</text>', svg)
    assert degrees == ["4", "3", "2", "1"]     # rows largest first: general, no flat, 12, 7
    sizes = [int(x) for x in re.findall(r'font-size="(\d+)"', svg)]
    assert sizes and min(sizes) >= 13
    assert "Operations per variant (add + mul + div): eq.mxm" in svg
    assert "Test CPU, 2 cores, 2026-01-02" in svg


def test_the_chart_names_this_machine_and_today_by_default() -> None:
    from max2code.machine import cpu, today
    from max2code.commands.report import chart

    svg = chart(_equation([("general", 4, 9)], [("general", 4, 5)]))
    assert cpu() in svg and today() in svg and 'class="missing"' not in svg
