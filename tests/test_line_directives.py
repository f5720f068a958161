"""Generated code points a debugger (or a reader) back at the .mxm line each coefficient came from.

* C and Modula-2 carry `#line` directives. Compiled with -g, gdb must stop at the .mxm line
  (the equation's last statement, for a module's coefficients; the term's line for a fragment),
  and the DWARF line table must say the same (`objdump --dwarf=decodedline`). After the
  coefficients a directive resumes the generated file's own numbering; the DWARF lines of the
  generated file's `return` must be right too.
* gm2 12 with -fcpp maps `#line N` to line N-1 (gcc maps it to N); the Modula-2 printer writes
  N+1. A control test compiles the same module without that correction and expects the quirk,
  so a gm2 that fixes it is noticed (then the correction must go: max2code/languages/m2/printer.py).
* Rust and Python carry `// file.mxm:LINE` and `# file.mxm:LINE` comments.

Tools: gcc, gm2, gdb, objdump. Under CI (CI set) a missing tool fails; elsewhere it skips.
"""

from __future__ import annotations

import dataclasses
import re
import subprocess
from pathlib import Path

import pytest

from conftest import corrected_paper_point_line, ROOT, require

from max2code.codegen.emit import module_name
from max2code.codegen.generate import generate, load
from max2code.languages import LANGUAGES

MXM = ROOT / "equations" / "circles-accel.mxm"
C_RUNTIME = ROOT / "runtime" / "c"
M2_RUNTIME = ROOT / "runtime" / "m2"


def last_statement_line(mxm: Path, starts: str) -> int:
    """Found in the text itself, not through max2code's parser."""
    lines = mxm.read_text().splitlines()
    return next(i for i, line in enumerate(lines, 1) if line.startswith(starts))


EXPECTED = last_statement_line(MXM, "(X1 - X2)^2")


def run(cmd: list[str], **kw: object) -> subprocess.CompletedProcess[str]:
    proc = subprocess.run(cmd, capture_output=True, text=True, **kw)  # type: ignore[call-overload]
    assert proc.returncode == 0, f"{' '.join(map(str, cmd))}\n{proc.stdout}\n{proc.stderr}"
    return proc


def dwarf_lines(obj: Path) -> dict[str, set[int]]:
    """File basename -> the line numbers the object's DWARF line table mentions for it."""
    out = run([require("objdump"), "--dwarf=decodedline", str(obj)]).stdout
    table: dict[str, set[int]] = {}
    for line in out.splitlines():
        fields = line.split()
        if len(fields) >= 3 and fields[1].isdigit() and fields[2].startswith("0x"):
            table.setdefault(fields[0], set()).add(int(fields[1]))
    return table


def gdb_stop(exe: Path, location: str, cwd: Path) -> str:
    """The line gdb prints when the program stops at a breakpoint on `location`."""
    gdb = require("gdb")
    out = run([gdb, "-batch", "-nx", "-ex", f"break {location}", "-ex", "run", "-ex", "frame",
               str(exe)], cwd=cwd, timeout=120).stdout
    # "Breakpoint 1, f (...) at file:line", or "Breakpoint 1.2, ..." with several locations
    # (one per variant of the module, all on the same .mxm line).
    stops = [line for line in out.splitlines() if re.match(r"Breakpoint 1(\.\d+)?, ", line)]
    assert stops, f"gdb never stopped at {location}:\n{out}"
    return stops[0]


def line_of(text: str, pattern: str) -> int:
    return next(i for i, line in enumerate(text.splitlines(), 1) if re.search(pattern, line))


# ---------------------------------------------------------------------------------------------
# C
# ---------------------------------------------------------------------------------------------

C_MAIN = """\
#include <stdio.h>
#include "circles_accel.h"
int main(void) {
    double p[circles_accel_NPARAMS] = {0};
    double t = 0.0;
    p[2] = 1.0; p[6] = 0.5; p[7] = 3.0; p[13] = 0.5; /* vx1, r1, x2, r2: touch at t = 2 */
    int status = circles_accel_first_root(p, 10.0, &t);
    printf("%d %g\\n", status, t);
    return 0;
}
"""


@pytest.fixture(scope="module")
def c_build(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path, str]:
    """(folder, executable, header text) of a C program using the circles-accel module."""
    gcc = require("gcc")
    folder = tmp_path_factory.mktemp("c-lines")
    spec, poly = load(str(MXM))
    header = folder / "circles_accel.h"
    text = generate(spec, poly, LANGUAGES["c"], "module", str(header)).text
    header.write_text(text)
    (folder / "main.c").write_text(C_MAIN)
    run([gcc, "-std=c11", "-g", "-O0", "-c", f"-I{C_RUNTIME}", "main.c", "-o", "main.o"],
        cwd=folder)
    run([gcc, "-std=c11", "-O2", "-c", f"-I{C_RUNTIME}", str(C_RUNTIME / "max2code_roots.c"),
         "-o", "roots.o"], cwd=folder)
    run([gcc, "main.o", "roots.o", "-o", "main", "-lgsl", "-lgslcblas", "-lm"], cwd=folder)
    assert run([str(folder / "main")]).stdout.split() == ["1", "2"]
    return folder, folder / "main", text


def test_c_dwarf_points_at_the_equation(c_build: tuple[Path, Path, str]) -> None:
    folder, _, text = c_build
    table = dwarf_lines(folder / "main.o")
    assert table.get(MXM.name) == {EXPECTED}, table
    # After the coefficients, the header's own numbering resumes: its `return` lines are right.
    returns = {i for i, line in enumerate(text.splitlines(), 1) if line.strip().startswith("return")}
    assert returns & table.get("circles_accel.h", set()), (sorted(returns), table)
    assert table["circles_accel.h"] <= set(range(1, len(text.splitlines()) + 1))


def test_gdb_stops_at_the_mxm_line_in_c(c_build: tuple[Path, Path, str]) -> None:
    folder, exe, _ = c_build
    stop = gdb_stop(exe, f"{MXM.name}:{EXPECTED}", folder)
    assert re.search(r"circles_accel_coefficients\w* \(", stop), stop
    assert stop.endswith(f"{MXM.name}:{EXPECTED}"), stop


# ---------------------------------------------------------------------------------------------
# Modula-2
# ---------------------------------------------------------------------------------------------

M2_MAIN = """\
MODULE Main ;
FROM circles_accel IMPORT FirstRoot, NParams ;
FROM STextIO IMPORT WriteString, WriteLn ;
VAR
   p: ARRAY [0..NParams-1] OF REAL ;
   i: CARDINAL ;
   t: REAL ;
BEGIN
   FOR i := 0 TO NParams-1 DO p[i] := 0.0 END ;
   p[2] := 1.0 ; p[6] := 0.5 ; p[7] := 3.0 ; p[13] := 0.5 ;
   IF FirstRoot(p, 10.0, t) AND (t = 2.0) THEN WriteString("ok") ELSE WriteString("wrong") END ;
   WriteLn
END Main.
"""


def build_m2(folder: Path, lang: object) -> tuple[Path, str]:
    """Compile the circles-accel module (printed by `lang`) and a main program; (exe, .mod)."""
    gm2 = require("gm2")
    gcc = require("gcc")
    spec, poly = load(str(MXM))
    name = module_name(spec)
    mod = folder / f"{name}.mod"
    result = generate(spec, poly, lang, "module", str(mod))  # type: ignore[arg-type]
    mod.write_text(result.text)
    for path, text in result.companions:
        Path(path).write_text(text)
    (folder / "Max2codeRoots.def").write_text((M2_RUNTIME / "Max2codeRoots.def").read_text())
    (folder / "Main.mod").write_text(M2_MAIN)
    run([gm2, "-fiso", "-fcpp", "-g", "-O0", "-c", mod.name, "-o", f"{name}.o"], cwd=folder)
    run([gcc, "-std=c11", "-O2", "-c", f"-I{C_RUNTIME}", str(C_RUNTIME / "max2code_roots.c"),
         "-o", "roots.o"], cwd=folder)
    iso = run([gm2, "-print-file-name=m2/m2iso"]).stdout.strip()
    run([gm2, "-fiso", "-g", "Main.mod", f"{name}.o", "roots.o", "-o", "main", f"-L{iso}",
         "-lm2iso", "-lpthread", "-lgsl", "-lgslcblas", "-lm"], cwd=folder)
    assert run([str(folder / "main")], cwd=folder).stdout.split() == ["ok"]
    return folder / "main", result.text


@pytest.fixture(scope="module")
def m2_build(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path, str]:
    folder = tmp_path_factory.mktemp("m2-lines")
    exe, text = build_m2(folder, LANGUAGES["m2"])
    return folder, exe, text


def test_m2_directives_are_written_one_line_later() -> None:
    spec, poly = load(str(MXM))
    text = generate(spec, poly, LANGUAGES["m2"], "module", "circles_accel.mod").text
    directives = {int(n) for n in re.findall(rf'^#line (\d+) "[^"]*{MXM.name}"$', text, re.M)}
    assert directives == {EXPECTED + 1}


def test_m2_dwarf_points_at_the_equation(m2_build: tuple[Path, Path, str]) -> None:
    folder, _, text = m2_build
    table = dwarf_lines(folder / "circles_accel.o")
    assert table.get(MXM.name) == {EXPECTED}, table
    # The implementation's own numbering resumes after the coefficients (the resume directive
    # carries the same +1): RETURN and the statements of FirstRoot are on their real lines.
    lines = text.splitlines()
    assert line_of(text, r"^\s+RETURN \d+$") in table["circles_accel.mod"], table
    assert line_of(text, r"degree := Coefficients\(p, c\)") in table["circles_accel.mod"], table
    assert max(table["circles_accel.mod"]) <= len(lines)


def test_gdb_stops_at_the_mxm_line_in_m2(m2_build: tuple[Path, Path, str]) -> None:
    folder, exe, _ = m2_build
    stop = gdb_stop(exe, f"{MXM.name}:{EXPECTED}", folder)
    assert re.search(r"(circles_accel_)?Coefficients\w* \(", stop), stop
    assert stop.endswith(f"{MXM.name}:{EXPECTED}"), stop


def test_gm2_still_maps_line_n_to_n_minus_1(tmp_path: Path) -> None:
    """Control: without the +1, this gm2 puts the coefficients one line early. If this fails,
    gm2 has been fixed and Modula2.line_offset must become 0."""
    uncorrected = dataclasses.replace(LANGUAGES["m2"], line_offset=0)
    build_m2(tmp_path, uncorrected)
    assert dwarf_lines(tmp_path / "circles_accel.o").get(MXM.name) == {EXPECTED - 1}


# ---------------------------------------------------------------------------------------------
# Fragments: each term's directive points at its `term K { ... }` line
# ---------------------------------------------------------------------------------------------

def test_m2_fragment_lines(tmp_path: Path) -> None:
    gm2 = require("gm2")
    mxm, term_lines = corrected_paper_point_line(tmp_path)
    spec, poly = load(str(mxm))
    result = generate(spec, poly, LANGUAGES["m2"], "fragment", str(tmp_path / "fragment.inc"))
    (tmp_path / "fragment.inc").write_text(result.text + "\n")
    (tmp_path / "Paper.mod").write_text(
        "MODULE Paper ;\n\nVAR\n   " + ", ".join(poly.parameters) + ": REAL ;\n\n"
        "PROCEDURE findSmallestPositiveRoot (VAR c: ARRAY OF REAL) : REAL ;\n"
        "BEGIN\n   RETURN c[0]\nEND findSmallestPositiveRoot ;\n\n"
        "PROCEDURE Predict ;\n#include \"fragment.inc\"\nEND Predict ;\n\n"
        "BEGIN\n   Predict\nEND Paper.\n")
    run([gm2, "-fiso", "-fcpp", "-g", "-c", "Paper.mod", "-o", "Paper.o"], cwd=tmp_path)
    text = mxm.read_text()
    finalise = line_of(text, r"findSmallestPositiveRoot\(coef\)")
    begin = line_of(text, r"^BEGIN$")  # the procedure's entry, in the initialise block
    assert dwarf_lines(tmp_path / "Paper.o").get(mxm.name) == {begin, *term_lines, finalise}


@pytest.mark.parametrize("lang,comment", [("rust", "//"), ("python", "#")])
def test_fragment_comments(tmp_path: Path, lang: str, comment: str) -> None:
    mxm, term_lines = corrected_paper_point_line(tmp_path)
    spec, poly = load(str(mxm))
    text = generate(spec, poly, LANGUAGES[lang], "fragment", "-").text
    pointers = re.findall(rf"^{re.escape(comment)} (.+):(\d+)$", text, re.M)
    terms = [int(n) for f, n in pointers if Path(f).name == mxm.name and int(n) in term_lines]
    assert terms == term_lines, text


# ---------------------------------------------------------------------------------------------
# Rust and Python modules: a comment before each coefficient
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("lang,comment", [("rust", "//"), ("python", "#")])
def test_module_comments(lang: str, comment: str) -> None:
    spec, poly = load(str(MXM))
    text = generate(spec, poly, LANGUAGES[lang], "module", "-").text
    lines = text.splitlines()
    pattern = re.compile(rf"^\s*{re.escape(comment)} (.+\.mxm):(\d+)$")
    pointers = [(i, m) for i, line in enumerate(lines) if (m := pattern.match(line))]
    assert len(pointers) >= poly.degree + 1, text
    for i, m in pointers:
        assert Path(m.group(1)) == MXM and int(m.group(2)) == EXPECTED, lines[i]
        following = lines[i + 1].strip()
        assert following and not following.startswith(comment), (lines[i], following)
