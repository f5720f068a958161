"""Named parameters in all four languages, compiled and run, against the oracle.

An equation whose parameters include names some language reserves (int, type, None, REAL,
self, lambda) beside ordinary ones (c, p), called through each language's named form: C's
struct and `_named` functions (and the index constants), Rust's `Params` (fields, `From` both
ways, methods), Python's mapping and `params(**kw)` (with errors naming missing and unknown
parameters), Modula-2's RECORD and `...Named` procedures. Every answer must match the positional
call bit for bit and the oracle (Maxima at exact rationals, mpmath roots) within the bounds of
tests/oracle.py. The field names a renamed parameter gets are the ones the warnings announce.
"""

from __future__ import annotations

import importlib.util
import shutil
import struct
import subprocess
from pathlib import Path

import pytest

from conftest import ROOT, require
from oracle import TMAX, Exact, check_sample, exact_coefficients, random_samples

from max2code.codegen.generate import generate, load
from max2code.languages import LANGUAGES

NAMED_MXM = """\
function named
parameters int, type, None, REAL, self, lambda, c, p
role still = type, None
begin
(int + type*t + None*t^2/2)^2 + (REAL + self*t)^2 - (c + p + lambda)^2;
end
"""
PARAMS = ("int", "type", "None", "REAL", "self", "lambda", "c", "p")
# The field each language gives each parameter, as its warnings say (checked below).
FIELDS = {
    "c": ("int_", "type", "None", "REAL", "self", "lambda", "c", "p"),
    "rust": ("int", "r#type", "None_", "REAL", "self_", "lambda", "c", "p"),
    "m2": ("int", "type", "None", "REAL_", "self", "lambda", "c", "p"),
}
SAMPLES = 40
C_RUNTIME = ROOT / "runtime" / "c"


@pytest.fixture(scope="module")
def equation(tmp_path_factory: pytest.TempPathFactory, maxima_exe: str):
    folder = tmp_path_factory.mktemp("named")
    mxm = folder / "named.mxm"
    mxm.write_text(NAMED_MXM)
    spec, poly = load(str(mxm))
    assert poly.parameters == PARAMS
    samples = random_samples(PARAMS, SAMPLES, seed=11)
    samples += [tuple(0.0 if n in ("type", "None") else v for n, v in zip(PARAMS, s))
                for s in samples[:6]]  # the variant `still`
    exact = exact_coefficients(mxm, PARAMS, samples)
    assert 5 <= sum(e.first_root(TMAX)[0] is not None for e in exact) <= len(exact) - 5
    return folder, spec, poly, exact


def hexline(e: Exact) -> str:
    return " ".join(float.hex(x) for x in (TMAX, *e.params)) + "\n"


def check_lines(lines: list[str], exact: list[Exact], label: str,
                decode=float.fromhex) -> None:
    """Each line: "named-result | positional-result", each "variant degree c.. | status t"."""
    assert len(lines) == len(exact), lines[-3:]
    for i, (line, e) in enumerate(zip(lines, exact)):
        named, positional = line.split(" || ")
        assert named == positional, f"{label} sample {i}: named {named} != positional {positional}"
        left, right = named.split(" | ")
        fields = left.split()
        coefs = [decode(x) for x in fields[2:]]
        assert int(fields[1]) == len(coefs) - 1
        status, t = right.split()
        assert int(fields[0]) == (0 if e.params[1] == e.params[2] == 0 else 1), label
        check_sample(e, coefs, decode(t) if status == "1" else None, f"{label} sample {i}")


def test_renamed_fields_are_announced(equation) -> None:
    _, spec, poly, _ = equation
    for lang, fields in FIELDS.items():
        result = generate(spec, poly, LANGUAGES[lang], "module", f"named{LANGUAGES[lang].extension}")
        renamed = {(n, f) for n, f in zip(PARAMS, fields) if f.removeprefix("r#") != n}
        said = {(w.message.split("'")[1], w.message.split("'")[3]) for w in result.warnings}
        assert said == renamed, lang
    python = generate(spec, poly, LANGUAGES["python"], "module", "named.py")
    assert python.warnings == ()  # a mapping names them as the .mxm does


C_DRIVER = r"""
#include <stdio.h>
#include "named.h"

static void show(int variant, int degree, const double c[], int status, double t)
{
    printf("%d %d", variant, degree);
    for (int i = 0; i <= degree; i++)
        printf(" %a", c[i]);
    printf(" | %d %a", status, status == 1 ? t : 0.0);
}

int main(void)
{
    named_params q;
    double tmax, p[named_NPARAMS], c[named_DEGREE + 1], t = 0.0;
    /* The index constants are the positions in named_param_names. */
    if (named_P_int_ != 0 || named_P_type != 1 || named_P_None != 2 || named_P_REAL != 3
        || named_P_self != 4 || named_P_lambda != 5 || named_P_c != 6 || named_P_p != 7)
        return 2;
    while (scanf("%la %la %la %la %la %la %la %la %la", &tmax, &q.int_, &q.type, &q.None,
                 &q.REAL, &q.self, &q.lambda, &q.c, &q.p) == 9) {
        int degree = named_coefficients_named(&q, c);
        int status = named_first_root_named(&q, tmax, &t);
        show(named_variant_named(&q), degree, c, status, t);
        printf(" || ");
        named_params_array(&q, p);
        degree = named_coefficients(p, c);
        status = named_first_root(p, tmax, &t);
        show(named_variant(p), degree, c, status, t);
        printf("\n");
    }
    return 0;
}
"""


def test_c_struct(equation, tmp_path: Path) -> None:
    gcc = require("gcc")
    _, spec, poly, exact = equation
    header = tmp_path / "named.h"
    header.write_text(generate(spec, poly, LANGUAGES["c"], "module", str(header)).text)
    (tmp_path / "main.c").write_text(C_DRIVER)
    subprocess.run([gcc, "-std=c11", "-Wall", "-Wextra", "-Werror", "-pedantic", f"-I{C_RUNTIME}",
                    f"-I{tmp_path}", str(tmp_path / "main.c"), str(C_RUNTIME / "max2code_roots.c"),
                    "-o", str(tmp_path / "named"), "-lgsl", "-lgslcblas", "-lm"], check=True)
    out = subprocess.run([str(tmp_path / "named")], input="".join(map(hexline, exact)),
                         capture_output=True, text=True, check=True).stdout
    check_lines(out.splitlines(), exact, "C")


def test_python_mapping_and_keywords(equation, tmp_path: Path) -> None:
    _, spec, poly, exact = equation
    out = tmp_path / "named_py.py"
    out.write_text(generate(spec, poly, LANGUAGES["python"], "module", str(out)).text)
    module_spec = importlib.util.spec_from_file_location("named_py", out)
    assert module_spec and module_spec.loader
    m = importlib.util.module_from_spec(module_spec)
    module_spec.loader.exec_module(m)
    lines = []
    for e in exact:
        mapping = dict(zip(PARAMS, e.params))
        assert m.params(mapping) == e.params == m.params(**mapping)
        assert m.params({"int": e.params[0]}, **{n: v for n, v in mapping.items() if n != "int"}) \
            == e.params
        results = []
        for p in (mapping, e.params):
            c, t = m.coefficients(p), m.first_root(p, TMAX)
            results.append(f"{m.variant(p)} {len(c) - 1} " + " ".join(float.hex(x) for x in c)
                           + (" | 0 0x0.0p+0" if t is None else f" | 1 {float.hex(t)}"))
        lines.append(" || ".join(results))
    check_lines(lines, exact, "Python")
    with pytest.raises(ValueError, match=r"^named: missing parameters: None, c$"):
        m.params({n: 1.0 for n in PARAMS if n not in ("None", "c")})
    with pytest.raises(ValueError, match=r"^named: unknown parameters: z, q$"):
        m.first_root({**dict.fromkeys(PARAMS, 1.0), "z": 1.0, "q": 2.0})
    with pytest.raises(ValueError, match=r"missing parameters: p; unknown parameters: P"):
        m.params(**{**{n: 1.0 for n in PARAMS if n != "p"}, "P": 1.0})


RUST_MAIN = r"""
#[allow(dead_code)]
mod named;
use named::Params;
use std::io::BufRead;

fn show(variant: usize, (degree, c): (usize, [f64; named::DEGREE + 1]), root: Option<f64>) -> String {
    let mut out = format!("{} {}", variant, degree);
    for x in &c[..=degree] {
        out += &format!(" {:016x}", x.to_bits());
    }
    match root {
        Some(t) => out + &format!(" | 1 {:016x}", t.to_bits()),
        None => out + " | 0 0",
    }
}

fn main() {
    for line in std::io::stdin().lock().lines() {
        let v: Vec<f64> = line
            .unwrap()
            .split_whitespace()
            .map(|w| f64::from_bits(u64::from_str_radix(w, 16).unwrap()))
            .collect();
        let tmax = v[0];
        let q = Params { int: v[1], r#type: v[2], None_: v[3], REAL: v[4], self_: v[5],
                         lambda: v[6], c: v[7], p: v[8] };
        let p: [f64; 8] = q.into();
        assert_eq!(Params::from(p), q);
        assert_eq!(p[..], v[1..]);
        let named = show(q.variant(), q.coefficients_degree(), q.first_root(tmax));
        assert_eq!(q.coefficients(), q.coefficients_degree().1);
        let positional = show(named::variant(&p), named::coefficients_degree(&p),
                              named::first_root(&p, tmax));
        println!("{named} || {positional}");
    }
}
"""


def test_rust_params(equation, tmp_path: Path) -> None:
    home = Path.home() / ".cargo" / "bin" / "cargo"
    cargo = shutil.which("cargo") or (str(home) if home.exists() else require("cargo"))
    _, spec, poly, exact = equation
    crate = tmp_path / "crate"
    (crate / "src").mkdir(parents=True)
    (crate / "src" / "named.rs").write_text(
        generate(spec, poly, LANGUAGES["rust"], "module", "named.rs").text)
    (crate / "src" / "main.rs").write_text(RUST_MAIN)
    (crate / "Cargo.toml").write_text(
        '[package]\nname = "named-test"\nversion = "0.0.0"\nedition = "2021"\npublish = false\n\n'
        f'[dependencies]\nmax2code-runtime = {{ path = "{(ROOT / "runtime" / "rust").as_posix()}" }}\n')
    env = {"CARGO_TARGET_DIR": str(ROOT / "build" / "test-cargo-target"), "RUSTFLAGS": "-D warnings",
           "PATH": f"{Path(cargo).parent}:/usr/bin:/bin", "HOME": str(Path.home())}
    subprocess.run([cargo, "build", "--release", "--quiet", "--offline"], cwd=crate, env=env,
                   check=True)
    binary = ROOT / "build" / "test-cargo-target" / "release" / "named-test"
    stdin = "".join(" ".join(f"{struct.unpack('<Q', struct.pack('<d', x))[0]:016x}"
                             for x in (TMAX, *e.params)) + "\n" for e in exact)
    out = subprocess.run([str(binary)], input=stdin, capture_output=True, text=True,
                         check=True).stdout
    check_lines(out.splitlines(), exact, "Rust",
                lambda s: struct.unpack("<d", struct.pack("<Q", int(s, 16)))[0])


M2_DRIVER = """\
MODULE Driver ;
FROM SYSTEM IMPORT CAST ;
FROM STextIO IMPORT WriteString, WriteLn, SkipLine ;
FROM SWholeIO IMPORT WriteCard, ReadCard ;
FROM SIOResult IMPORT ReadResult, ReadResults ;
FROM named IMPORT Params, ParamsArray, CoefficientsNamed, FirstRootNamed, VariantNamed,
   Coefficients, FirstRoot, Variant, NParams, Degree ;

TYPE
   Halves = ARRAY [0..1] OF CARDINAL ;

VAR
   q: Params ;
   p: ARRAY [0..NParams-1] OF REAL ;
   tmax: REAL ;

PROCEDURE Get (VAR x: REAL) : BOOLEAN ;
VAR
   h: Halves ;
BEGIN
   ReadCard(h[0]) ;
   IF ReadResult() # allRight THEN RETURN FALSE END ;
   ReadCard(h[1]) ;
   IF ReadResult() # allRight THEN RETURN FALSE END ;
   x := CAST(REAL, h) ;
   RETURN TRUE
END Get ;

PROCEDURE Put (x: REAL) ;
VAR
   h: Halves ;
BEGIN
   h := CAST(Halves, x) ;
   WriteString(" ") ; WriteCard(h[0], 0) ; WriteString(":") ; WriteCard(h[1], 0)
END Put ;

PROCEDURE Show (variant, degree: CARDINAL; VAR c: ARRAY OF REAL; found: BOOLEAN; t: REAL) ;
VAR
   i: CARDINAL ;
BEGIN
   WriteCard(variant, 0) ; WriteString(" ") ; WriteCard(degree, 0) ;
   FOR i := 0 TO degree DO Put(c[i]) END ;
   IF found THEN WriteString(" | 1") ELSE WriteString(" | 0") ; t := 0.0 END ;
   Put(t)
END Show ;

PROCEDURE Run ;
VAR
   c: ARRAY [0..Degree] OF REAL ;
   degree: CARDINAL ;
   found: BOOLEAN ;
   t: REAL ;
BEGIN
   t := 0.0 ;
   degree := CoefficientsNamed(q, c) ;
   found := FirstRootNamed(q, tmax, t) ;
   Show(VariantNamed(q), degree, c, found, t) ;
   WriteString(" ||") ;
   ParamsArray(q, p) ;
   degree := Coefficients(p, c) ;
   found := FirstRoot(p, tmax, t) ;
   Show(Variant(p), degree, c, found, t) ;
   WriteLn
END Run ;

BEGIN
   WHILE Get(tmax) AND Get(q.int) AND Get(q.type) AND Get(q.None) AND Get(q.REAL_)
         AND Get(q.self) AND Get(q.lambda) AND Get(q.c) AND Get(q.p) DO
      SkipLine ;
      Run
   END
END Driver.
"""


def test_m2_record(equation, tmp_path: Path) -> None:
    gm2, gcc = require("gm2"), require("gcc")
    _, spec, poly, exact = equation
    result = generate(spec, poly, LANGUAGES["m2"], "module", str(tmp_path / "named.mod"))
    (tmp_path / "named.mod").write_text(result.text)
    for path, text in result.companions:
        Path(path).write_text(text)
    shutil.copy(ROOT / "runtime" / "m2" / "Max2codeRoots.def", tmp_path)
    (tmp_path / "Driver.mod").write_text(M2_DRIVER)
    iso = subprocess.run([gm2, "-print-file-name=m2/m2iso"], capture_output=True, text=True,
                         check=True).stdout.strip()

    def run(cmd: list[str]) -> None:
        proc = subprocess.run(cmd, cwd=tmp_path, capture_output=True, text=True)
        assert proc.returncode == 0, proc.stdout + proc.stderr

    run([gcc, "-std=c11", f"-I{C_RUNTIME}", "-c", str(C_RUNTIME / "max2code_roots.c"), "-o",
         "roots.o"])
    run([gm2, "-fiso", "-fcpp", "-Wall", "-Werror", "-c", "named.mod", "-o", "named.o"])
    run([gm2, "-fiso", "Driver.mod", "named.o", "roots.o", "-o", "driver", f"-L{iso}",
         "-lm2iso", "-lpthread", "-lgsl", "-lgslcblas", "-lm"])

    def halves(x: float) -> str:
        lo, hi = struct.unpack("<II", struct.pack("<d", x))
        return f"{lo} {hi}"

    stdin = "".join(" ".join(halves(x) for x in (TMAX, *e.params)) + " \n" for e in exact)
    out = subprocess.run([str(tmp_path / "driver")], input=stdin, capture_output=True, text=True,
                         check=True).stdout

    def decode(s: str) -> float:
        lo, hi = s.split(":")
        return struct.unpack("<d", struct.pack("<II", int(lo), int(hi)))[0]

    check_lines([line.replace(" ||", " || ", 1).replace(" ||  ", " || ") for line in
                 out.splitlines()], exact, "Modula-2", decode)
