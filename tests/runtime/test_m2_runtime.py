"""The Modula-2 runtime (runtime/m2/Max2codeRoots.def) against the shared hard cases.

Max2codeRoots is a DEFINITION MODULE FOR "C" of the C runtime, so what is tested here is
the binding: a Modula-2 line driver (below), built once per session with gm2 -fiso -fcpp
and linked with the C runtime object, GSL and the ISO libraries, calls m2c_first_root_ex
for every case and method; the results are judged exactly as tests/runtime/test_c_runtime.py
judges the C driver's (cases.judge, the same per-case bounds, the same random-polynomial
bounds), and must be bit-identical to the C driver's, linked with the very same object.

Numbers cross into and out of Modula-2 as IEEE bit patterns (16 hex digits), so nothing is
lost in decimal.  Tools: gm2, gcc and the GSL headers; under CI (CI set) a missing tool fails,
elsewhere the tests skip.  M2C_M2_RANDOM_CASES sets the number of random polynomials (400).
"""
from __future__ import annotations

import math
import os
import shutil
import struct
import subprocess
from pathlib import Path
from typing import Sequence

import pytest

from conftest import require

from . import cases
from . import test_c_runtime as c_test

ROOT = Path(__file__).resolve().parents[2]
C_DIR = ROOT / "runtime" / "c"
M2_DIR = ROOT / "runtime" / "m2"
METHODS = c_test.C_METHODS  # the binding's method numbers are the C runtime's
RANDOM_COUNT = int(os.environ.get("M2C_M2_RANDOM_CASES", "400"))
SENTINEL = 0x7FF8DEADBEEF0001  # t before each call (a NaN); graze starts as 7

Result = tuple[int, float, bool]

# The real's IEEE bit pattern as 16 hex digits (both Modula-2 programs below print with it).
PUT_REAL = """\
PROCEDURE PutReal (x: REAL) ;
VAR
   b: Bits ;
   k: INTEGER ;
   d: CARDINAL ;
   s: ARRAY [0..16] OF CHAR ;
BEGIN
   b := CAST(Bits, x) ;
   FOR k := 15 TO 0 BY -1 DO
      d := VAL(CARDINAL, b MOD 16) ;
      IF d < 10 THEN s[k] := CHR(ORD('0') + d) ELSE s[k] := CHR(ORD('a') + d - 10) END ;
      b := b DIV 16
   END ;
   s[16] := 0C ;
   WriteString(s)
END PutReal ;
"""

M2_DRIVER = """\
MODULE RootsDriver ;
(* Line driver for the stability tests: each input line
      METHOD TMAX DEGREE C0 .. CN
   with METHOD and DEGREE decimal integers and every real a 16-hex-digit IEEE bit pattern;
   N = DEGREE, but at most MaxRead + 1 coefficients are read (none for DEGREE < 0), as
   runtime/c/max2code_roots_driver.c does.  Each output line: STATUS T GRAZE, with T as a
   16-hex-digit bit pattern.  t and graze start as a NaN sentinel and 7 and are printed even
   when STATUS is not 1, so that the caller can see that the runtime left them alone. *)
FROM SYSTEM IMPORT CAST ;
FROM STextIO IMPORT ReadToken, SkipLine, WriteString, WriteLn ;
FROM SWholeIO IMPORT WriteInt ;
FROM SIOResult IMPORT ReadResult ;
FROM IOConsts IMPORT ReadResults ;
FROM WholeStr IMPORT StrToInt ;
FROM ConvTypes IMPORT ConvResults ;
FROM Strings IMPORT Length ;
FROM Max2codeRoots IMPORT m2c_first_root_ex ;

CONST
   MaxRead = 16 ;
   Sentinel = 0{sentinel:016X}H ;

TYPE
   Bits = LONGCARD ;

VAR
   tok: ARRAY [0..63] OF CHAR ;
   c: ARRAY [0..MaxRead] OF REAL ;
   method, degree, graze, status, want, i: INTEGER ;
   tmax, t: REAL ;
   r: ReadResults ;
   sentinel: Bits ;

PROCEDURE Fail (what: ARRAY OF CHAR) ;
BEGIN
   WriteString("error: ") ; WriteString(what) ; WriteString(" '") ; WriteString(tok) ;
   WriteString("'") ; WriteLn ;
   HALT(2)
END Fail ;

PROCEDURE Next ;
BEGIN
   ReadToken(tok) ;
   IF ReadResult() # allRight THEN Fail("missing field") END
END Next ;

PROCEDURE ToInt () : INTEGER ;
VAR
   n: INTEGER ;
   res: ConvResults ;
BEGIN
   StrToInt(tok, n, res) ;
   IF res # strAllRight THEN Fail("not an integer") END ;
   RETURN n
END ToInt ;

PROCEDURE Int () : INTEGER ;
BEGIN
   Next ;
   RETURN ToInt()
END Int ;

PROCEDURE Real () : REAL ;
VAR
   b: Bits ;
   k, d: CARDINAL ;
BEGIN
   Next ;
   IF Length(tok) # 16 THEN Fail("not 16 hex digits") END ;
   b := 0 ;
   FOR k := 0 TO 15 DO
      CASE tok[k] OF
         '0'..'9': d := ORD(tok[k]) - ORD('0') |
         'a'..'f': d := ORD(tok[k]) - ORD('a') + 10 |
         'A'..'F': d := ORD(tok[k]) - ORD('A') + 10
      ELSE
         Fail("not a hex digit")
      END ;
      b := b * 16 + VAL(Bits, d)
   END ;
   RETURN CAST(REAL, b)
END Real ;

{put_real}
PROCEDURE Query ;  (* the line's first token, METHOD, is in tok *)
BEGIN
   method := ToInt() ;
   tmax := Real() ;
   degree := Int() ;
   IF degree < 0 THEN want := 0 ELSIF degree > MaxRead THEN want := MaxRead + 1
   ELSE want := degree + 1 END ;
   FOR i := 0 TO want - 1 DO c[i] := Real() END ;
   (* Ignore the rest of the line.  Not SkipLine alone: gm2 12's SkipLine loops forever at
      the end of input when it has characters to skip before the line mark. *)
   REPEAT ReadToken(tok) UNTIL ReadResult() # allRight ;
   IF ReadResult() = endOfLine THEN SkipLine END ;
   sentinel := Sentinel ;  (* via a variable: gm2 converts the value in CAST(REAL, constant) *)
   t := CAST(REAL, sentinel) ;
   graze := 7 ;
   status := m2c_first_root_ex(c, degree, tmax, t, method, graze) ;
   WriteInt(status, 0) ; WriteString(" ") ; PutReal(t) ; WriteString(" ") ;
   WriteInt(graze, 0) ; WriteLn
END Query ;

BEGIN
   LOOP
      ReadToken(tok) ;
      r := ReadResult() ;
      IF r = endOfInput THEN EXIT
      ELSIF r = endOfLine THEN SkipLine  (* an empty line *)
      ELSIF r = allRight THEN Query
      ELSE Fail("unreadable input")
      END
   END
END RootsDriver.
"""


# ---------------------------------------------------------------------------
# Building and running the drivers
# ---------------------------------------------------------------------------

def _run(cmd: list[str], cwd: Path) -> None:
    r = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    assert r.returncode == 0, f"{' '.join(cmd)}\n{r.stdout}\n{r.stderr}"
    assert r.stderr == "", f"{' '.join(cmd)} said something:\n{r.stderr}"


@pytest.fixture(scope="session")
def drivers(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    """(Modula-2 driver, C driver), both linked with one object of the C runtime (strict
    flags, as test_c_runtime.py compiles it): any difference between them is the binding's."""
    gcc = require("gcc")
    gm2 = require("gm2")
    if not Path("/usr/include/gsl/gsl_poly.h").exists() and subprocess.run(
            [gcc, "-E", "-x", "c", "-", "-o", os.devnull], input="#include <gsl/gsl_poly.h>\n",
            text=True, capture_output=True).returncode != 0:
        c_test._missing("GSL headers (libgsl-dev) not found")
    work = tmp_path_factory.mktemp("m2_runtime")
    obj = work / "max2code_roots.o"
    _run([gcc, *c_test.STRICT, "-I", str(C_DIR), "-c", str(C_DIR / "max2code_roots.c"),
          "-o", str(obj)], work)
    libs = ["-lgsl", "-lgslcblas", "-lm"]
    _run([gcc, *c_test.STRICT, "-I", str(C_DIR), str(C_DIR / "max2code_roots_driver.c"),
          str(obj), "-o", "c_driver", *libs], work)
    shutil.copy(M2_DIR / "Max2codeRoots.def", work)
    (work / "RootsDriver.mod").write_text(M2_DRIVER.format(sentinel=SENTINEL, put_real=PUT_REAL))
    iso = subprocess.run([gm2, "-print-file-name=m2/m2iso"], capture_output=True, text=True,
                         check=True).stdout.strip()
    _run([gm2, "-fiso", "-fcpp", "-g", "-Wall", "-Werror", "RootsDriver.mod", str(obj),
          "-o", "m2_driver", f"-L{iso}", "-lm2iso", "-lpthread", *libs], work)
    return work / "m2_driver", work / "c_driver"


def _bits(x: float) -> str:
    return f"{struct.unpack('<Q', struct.pack('<d', x))[0]:016x}"


def _float(h: str) -> float:
    return struct.unpack("<d", struct.pack("<Q", int(h, 16)))[0]


def m2_line(method: str | int, c: Sequence[float], tmax: float, degree: int | None = None) -> str:
    deg = len(c) - 1 if degree is None else degree
    m = METHODS[method] if isinstance(method, str) else method
    return " ".join([str(m), _bits(tmax), str(deg), *(_bits(float(x)) for x in c)])


def run_m2_raw(exe: Path, lines: Sequence[str]) -> list[tuple[int, int, int]]:
    """(status, bit pattern of t, graze) per line, t and graze as the driver printed them
    (the sentinels when the runtime did not write them)."""
    r = subprocess.run([str(exe)], input="\n".join(lines) + "\n", capture_output=True, text=True,
                       timeout=120)
    assert r.returncode == 0 and r.stderr == "", f"rc {r.returncode}\n{r.stdout[-2000:]}\n{r.stderr}"
    out = []
    for text in r.stdout.splitlines():
        st, t, g = text.split()  # gm2's ISO WriteInt writes a sign: +1, +0, -1
        assert len(t) == 16, text
        out.append((int(st), int(t, 16), int(g)))
    assert len(out) == len(lines)
    return out


def run_m2(exe: Path, lines: Sequence[str]) -> list[Result]:
    """As test_c_runtime.run_driver reports: (status, t, graze), t nan unless status is 1."""
    out = []
    for st, t, g in run_m2_raw(exe, lines):
        assert g in (0, 1, 7), g
        out.append((st, _float(f"{t:016x}") if st == 1 else math.nan, st == 1 and g == 1))
    return out


# ---------------------------------------------------------------------------
# Hard cases: judged as the C runtime's
# ---------------------------------------------------------------------------

ALL = cases.all_cases()
KEYS = [(case.name, m) for case in ALL for m in METHODS]


@pytest.fixture(scope="module")
def case_results(drivers: tuple[Path, Path]) -> dict[tuple[str, str], Result]:
    by_name = {c.name: c for c in ALL}
    lines = [m2_line(m, by_name[n].coeffs, by_name[n].tmax) for n, m in KEYS]
    return dict(zip(KEYS, run_m2(drivers[0], lines)))


@pytest.mark.parametrize("method", list(METHODS))
@pytest.mark.parametrize("case", ALL, ids=[c.name for c in ALL])
def test_case(case: cases.Case, method: str, case_results: dict[tuple[str, str], Result]) -> None:
    st, t, g = case_results[(case.name, method)]
    why = cases.judge(case, method, st, t, g)
    assert why is None, f"{case.name} [{method}]: {why}"


def test_same_bits_as_the_c_driver(drivers: tuple[Path, Path]) -> None:
    """Every hard case and random polynomial, every method: the Modula-2 results are the C
    driver's bit for bit (the C driver prints %.17g, which identifies a double exactly)."""
    m2, c = drivers
    queries = [(m, case.coeffs, case.tmax) for case in ALL for m in METHODS]
    queries += [(m, rc.coeffs, rc.tmax) for rc in cases.random_cases(RANDOM_COUNT) for m in METHODS]
    got = run_m2_raw(m2, [m2_line(m, cf, tmax) for m, cf, tmax in queries])
    want = c_test.run_driver(c, [c_test._line(m, cf, tmax) for m, cf, tmax in queries])
    diffs = []
    for (m, cf, tmax), (st, t, g), (cst, ct, cg) in zip(queries, got, want):
        if st != cst or (st == 1 and (t != int(_bits(ct), 16) or g != int(cg))):
            diffs.append(f"[{m}] {cf} tmax={tmax}: Modula-2 {st} {t:016x} {g}, "
                         f"C {cst} {_bits(ct)} {int(cg)}")
    assert not diffs, f"{len(diffs)} of {len(queries)} differ, first:\n" + "\n".join(diffs[:10])


def test_t_and_graze_untouched_without_a_root(drivers: tuple[Path, Path]) -> None:
    """The contract (max2code_roots.h): t and graze are written only when 1 is returned; the
    VAR parameters of the binding must not change that."""
    queries = [(m, case.coeffs, case.tmax) for case in ALL for m in METHODS]
    got = run_m2_raw(drivers[0], [m2_line(m, cf, tmax) for m, cf, tmax in queries])
    statuses = {st for st, _, _ in got}
    assert statuses == {-1, 0, 1}, statuses
    for (m, cf, tmax), (st, t, g) in zip(queries, got):
        if st != 1:
            assert (t, g) == (SENTINEL, 7), f"[{m}] {cf} tmax={tmax}: status {st}, t {t:016x}, graze {g}"
        else:
            assert g in (0, 1) and 0 < _float(f"{t:016x}") <= tmax, (m, cf, tmax, hex(t), g)


def test_graze_flag_and_nograze(drivers: tuple[Path, Path]) -> None:
    """As for C: a touch is reported with graze=1; without the check it is missed and the
    solver goes on to the next crossing."""
    exe = drivers[0]
    c = cases.poly_from_roots(["2", "2", "5", "-1"])  # exact coefficients
    res = run_m2(exe, [m2_line("interval", c, math.inf), m2_line("interval-nograze", c, math.inf),
                       m2_line("gsl", c, math.inf)])
    # a touch inside compensated Horner's band stands only where p is certainly positive
    # just before it (issue 33, item 11): the band's left edge, a few ulps early
    assert res[0][0] == 1 and res[0][2] and 2 * (1 - 2.0**-46) <= res[0][1] <= 2.0, res[0]
    assert res[1][0] == 1 and res[1][1] == 2.0  # p(2) is exactly 0: reported without the check
    c2 = cases.poly_from_roots(["1", "1", "5"], [("0", "1")])  # (t-1)^2 (t-5)(t^2+1)
    c2 = (c2[0] * (1 + 2.0**-52),) + c2[1:]  # nudge: no exact zero at the touch
    res = run_m2(exe, [m2_line("interval", c2, math.inf), m2_line("interval-nograze", c2, math.inf)])
    assert res[0][0] == 1 and res[0][2] and abs(res[0][1] - 1) < 1e-7
    assert res[1][0] == 1 and abs(res[1][1] - 5) < 1e-12, "nograze should skip the touch"


def test_invalid_degree_and_method(drivers: tuple[Path, Path]) -> None:
    c = (1.0, -3.0, 2.0)
    lines = [
        m2_line(0, (1.0,), math.inf, degree=-1),
        m2_line(0, (1.0,) * 18, math.inf, degree=17),
        m2_line(7, c, math.inf),
        m2_line(-1, c, math.inf),
        m2_line(0, c, math.inf),  # the same polynomial, valid: root 0.5
    ]
    assert [r[0] for r in run_m2(drivers[0], lines)] == [-1, -1, -1, -1, 1]


# ---------------------------------------------------------------------------
# Random polynomials: the C runtime's bounds
# ---------------------------------------------------------------------------

def test_random(drivers: tuple[Path, Path]) -> None:
    rc = cases.random_cases(RANDOM_COUNT)
    keys = [(case, m) for case in rc for m in METHODS]
    res = run_m2(drivers[0], [m2_line(m, case.coeffs, case.tmax) for case, m in keys])
    bad = list(cases.random_failures([(case, m, r) for (case, m), r in zip(keys, res)]))
    assert not bad, f"{len(bad)} failures, first: " + "\n".join(bad[:10])


def test_report_worst_errors(case_results: dict[tuple[str, str], Result],
                             capsys: pytest.CaptureFixture[str]) -> None:
    """Prints the worst relative error per family and method (run with -s); the same table
    as the C runtime's, since the numbers are the same."""
    table = cases.format_worst(cases.worst_errors(case_results), "Modula-2 runtime: worst relative error")
    with capsys.disabled():
        print("\n" + table)


SKIN_AND_BATCH = """\
MODULE SkinBatch ;
(* The contact skin and the batch entry point through the binding: prints
   status, t (bits), graze for ((t-1)^2 + 1e-9)(3 - t) without and with a skin of 1e-8,
   then the batch count and its two roots (bits). *)
FROM SYSTEM IMPORT CAST ;
FROM STextIO IMPORT WriteString, WriteLn ;
FROM SWholeIO IMPORT WriteInt ;
FROM Max2codeRoots IMPORT m2c_first_root_skin, m2c_first_roots ;

TYPE
   Bits = LONGCARD ;

VAR
   c: ARRAY [0..3] OF REAL ;
   rows: ARRAY [0..5] OF REAL ;
   ts: ARRAY [0..1] OF REAL ;
   st: ARRAY [0..1] OF INTEGER ;
   t: REAL ;
   g, r: INTEGER ;

{put_real}
BEGIN
   c[0] := 3.0 * (1.0 + 1.0E-9) ; c[1] := -(7.0 + 1.0E-9) ; c[2] := 5.0 ; c[3] := -1.0 ;
   r := m2c_first_root_skin(c, 3, 1.0E300, 0.0, t, g) ;
   WriteInt(r, 0) ; WriteString(" ") ; PutReal(t) ; WriteString(" ") ; WriteInt(g, 0) ; WriteLn ;
   r := m2c_first_root_skin(c, 3, 1.0E300, 1.0E-8, t, g) ;
   WriteInt(r, 0) ; WriteString(" ") ; PutReal(t) ; WriteString(" ") ; WriteInt(g, 0) ; WriteLn ;
   rows[0] := 2.0 ; rows[1] := -3.0 ; rows[2] := 1.0 ;
   rows[3] := 1.0 ; rows[4] := 1.0 ; rows[5] := 1.0 ;
   r := m2c_first_roots(rows, 2, 2, 1.0E300, 0.0, ts, st) ;
   WriteInt(r, 0) ; WriteString(" ") ; PutReal(ts[0]) ; WriteString(" ") ; WriteInt(st[1], 0) ; WriteLn
END SkinBatch.
"""


def test_skin_and_batch_through_the_binding(tmp_path: Path) -> None:
    """m2c_first_root_skin and m2c_first_roots called from Modula-2: the crossing at 3 without
    a skin, the touch at 1 (graze) with it; the batch finds one root (1) of two rows."""
    gcc, gm2 = require("gcc"), require("gm2")
    obj = tmp_path / "max2code_roots.o"
    _run([gcc, *c_test.STRICT, "-I", str(C_DIR), "-c", str(C_DIR / "max2code_roots.c"), "-o", str(obj)],
         tmp_path)
    shutil.copy(M2_DIR / "Max2codeRoots.def", tmp_path)
    (tmp_path / "SkinBatch.mod").write_text(SKIN_AND_BATCH.format(put_real=PUT_REAL))
    iso = subprocess.run([gm2, "-print-file-name=m2/m2iso"], capture_output=True, text=True,
                         check=True).stdout.strip()
    _run([gm2, "-fiso", "-g", "-Wall", "SkinBatch.mod", str(obj), "-o", "skin_batch", f"-L{iso}",
          "-lm2iso", "-lpthread", "-lgsl", "-lgslcblas", "-lm"], tmp_path)
    out = subprocess.run([str(tmp_path / "skin_batch")], capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    lines = [ln.split() for ln in out.stdout.splitlines()]
    st, t, g = int(lines[0][0]), _float(lines[0][1]), int(lines[0][2])
    assert st == 1 and abs(t - 3.0) < 1e-14 and g == 0
    st, t, g = int(lines[1][0]), _float(lines[1][1]), int(lines[1][2])
    assert st == 1 and abs(t - 1.0) < 1e-6 and g == 1
    assert int(lines[2][0]) == 1 and _float(lines[2][1]) == 1.0 and int(lines[2][2]) == 0
