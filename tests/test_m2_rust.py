"""Generated Modula-2 and Rust, compiled and run, against Maxima evaluating the original equation.

For every shipped equation (equations/*.mxm): 120 random parameter sets (the same as
tests/test_generated.py draws for C and Python); the generated module's coefficients and first
root are compared with the exact coefficients (Maxima, rational arithmetic, the user's program as
written: tests/oracle.py) and the exact first root (mpmath, 60 digits).

Numbers cross the language boundary as IEEE bit patterns, so nothing is lost in decimal.
* Modula-2: gm2 -fiso -fcpp; the driver embeds the samples as pairs of 32-bit halves.
* Rust: one crate (all equations as modules, plus the keyword equation) depending on
  runtime/rust by path, built once per session with `-D warnings` and checked with
  `cargo clippy -- -D warnings`. CARGO_TARGET_DIR is build/test-cargo-target (gitignored), so
  a second run only rebuilds what changed.

Also: an equation whose parameters are keywords somewhere (type, match, self, VAR, TYPE, int,
char, BEGIN) compiles and computes the right coefficients in all four languages, and the
paper's Modula-2 fragment use (initialise / terms / finalise) compiles.

Tools: gm2, gcc, cargo. Under CI (CI set) a missing tool fails; elsewhere the test skips.
"""

from __future__ import annotations

import importlib.util
import os
import shutil
import struct
import subprocess
import zlib
from pathlib import Path

import pytest

from conftest import corrected_paper_point_line, ROOT, require
from oracle import TMAX, Exact, check_sample, exact_coefficients, random_samples, sampled_equation

from max2code.diagnostics import Pos
from max2code.codegen.emit import module_name
from max2code.codegen.generate import generate, load
from max2code.languages import LANGUAGES
from max2code.codegen.names import choose
from max2code.codegen.variants import family

EQUATIONS = sorted((ROOT / "equations").glob("*.mxm"))
SAMPLES = 120
CARGO_TARGET = ROOT / "build" / "test-cargo-target"
C_RUNTIME = ROOT / "runtime" / "c"
M2_RUNTIME = ROOT / "runtime" / "m2"
RUST_RUNTIME = ROOT / "runtime" / "rust"

KEYWORDS_MXM = """\
// Parameter names that are keywords in some target language: each printer mangles its own.
function keywords
parameters type, match, self, VAR, TYPE, int, char, BEGIN

begin
(type + match*t + self*t^2)*VAR - TYPE*int*t + char*BEGIN*t^3 - 1;
end
"""
KEYWORD_PARAMS = (0.75, -1.5, 2.25, 3.0, -0.5, 1.25, 4.5, -0.125)


def keyword_coefficients(p: tuple[float, ...]) -> list[float]:
    type_, match, self_, var, type_uc, int_, char, begin = p
    return [var * type_ - 1.0, var * match - type_uc * int_, var * self_, begin * char]


# ---------------------------------------------------------------------------------------------
# Tools
# ---------------------------------------------------------------------------------------------

def gm2_link_flags(gm2: str) -> list[str]:
    iso = subprocess.run([gm2, "-print-file-name=m2/m2iso"], capture_output=True, text=True,
                         check=True).stdout.strip()
    return [f"-L{iso}", "-lm2iso", "-lpthread", "-lgsl", "-lgslcblas", "-lm"]


def cargo_exe() -> str:
    found = shutil.which("cargo")
    home = Path.home() / ".cargo" / "bin" / "cargo"
    if found is None and home.exists():
        return str(home)
    return require("cargo")


def run(cmd: list[str], **kw: object) -> subprocess.CompletedProcess[str]:
    """Run a build step; on failure show its output in the assertion message."""
    proc = subprocess.run(cmd, capture_output=True, text=True, **kw)  # type: ignore[call-overload]
    assert proc.returncode == 0, f"{' '.join(map(str, cmd))}\n{proc.stdout}\n{proc.stderr}"
    return proc


def bits(x: float) -> tuple[int, int]:
    """The low and high 32-bit halves of a double (x86-64 is little-endian)."""
    return struct.unpack("<II", struct.pack("<d", x))


def from_halves(lo: str, hi: str) -> float:
    return struct.unpack("<d", struct.pack("<II", int(lo), int(hi)))[0]


@pytest.fixture(scope="session")
def c_runtime_object(tmp_path_factory: pytest.TempPathFactory) -> Path:
    gcc = require("gcc")
    obj = tmp_path_factory.mktemp("c-runtime") / "max2code_roots.o"
    run([gcc, "-std=c11", "-O2", "-g", f"-I{C_RUNTIME}", "-c", str(C_RUNTIME / "max2code_roots.c"),
         "-o", str(obj)])
    return obj


# ---------------------------------------------------------------------------------------------
# The oracle, per equation
# ---------------------------------------------------------------------------------------------

@pytest.fixture(scope="module", params=EQUATIONS, ids=lambda p: p.stem)
def equation(request: pytest.FixtureRequest, maxima_exe: str) -> tuple[Path, object, list[Exact]]:
    spec, poly, exact = sampled_equation(request.param, SAMPLES)
    return request.param, (spec, poly), exact


# ---------------------------------------------------------------------------------------------
# Modula-2
# ---------------------------------------------------------------------------------------------

M2_DRIVER = """\
MODULE Driver ;
(* Runs {name} on samples embedded as IEEE bit patterns; prints bit patterns back. *)
FROM SYSTEM IMPORT CAST ;
FROM STextIO IMPORT WriteString, WriteLn ;
FROM SWholeIO IMPORT WriteCard ;
FROM {name} IMPORT Coefficients, FirstRoot, ParamName, Variant, VariantName, NParams, Degree,
   NVariants ;

TYPE
   Halves = ARRAY [0..1] OF CARDINAL ;

VAR
   p: ARRAY [0..NParams-1] OF REAL ;

PROCEDURE Bits (lo, hi: CARDINAL) : REAL ;
VAR
   h: Halves ;
BEGIN
   h[0] := lo ; h[1] := hi ;
   RETURN CAST(REAL, h)
END Bits ;

PROCEDURE Put (x: REAL) ;
VAR
   h: Halves ;
BEGIN
   h := CAST(Halves, x) ;
   WriteString(" ") ; WriteCard(h[0], 0) ; WriteString(" ") ; WriteCard(h[1], 0)
END Put ;

PROCEDURE Meta ;
VAR
   i: CARDINAL ;
   name: ARRAY [0..255] OF CHAR ;
BEGIN
   WriteCard(NParams, 0) ; WriteString(" ") ; WriteCard(Degree, 0) ;
   FOR i := 0 TO NParams-1 DO
      ParamName(i, name) ; WriteString(" ") ; WriteString(name)
   END ;
   WriteLn ;
   FOR i := 0 TO NVariants-1 DO
      VariantName(i, name) ; WriteString(name) ; WriteLn
   END
END Meta ;

PROCEDURE Sample ;
VAR
   c: ARRAY [0..Degree] OF REAL ;
   i, degree: CARDINAL ;
   t: REAL ;
BEGIN
   WriteCard(Variant(p), 0) ; WriteString(" ") ;
   degree := Coefficients(p, c) ;
   WriteCard(degree, 0) ;
   FOR i := 0 TO degree DO Put(c[i]) END ;
   t := 0.0 ;
   IF FirstRoot(p, {tmax}, t) THEN WriteString(" | 1") ELSE WriteString(" | 0") END ;
   Put(t) ;
   WriteLn
END Sample ;

BEGIN
   Meta ;
{samples}
END Driver.
"""


def build_m2(mxm: Path, workdir: Path, samples: list[tuple[float, ...]], runtime_obj: Path,
             tmax: float = TMAX) -> list[str]:
    """Generate NAME.mod + NAME.def, compile them and a driver with gm2, run; output lines."""
    gm2 = require("gm2")
    spec, poly = load(str(mxm))
    name = module_name(spec)
    out = workdir / f"{name}.mod"
    result = generate(spec, poly, LANGUAGES["m2"], "module", str(out))
    out.write_text(result.text)
    assert [Path(p).name for p, _ in result.companions] == [f"{name}.def"]
    for path, text in result.companions:
        Path(path).write_text(text)
    shutil.copy(M2_RUNTIME / "Max2codeRoots.def", workdir)
    lines = []
    for sample in samples:
        for k, v in enumerate(sample):
            lo, hi = bits(v)
            lines.append(f"   p[{k}] := Bits({lo}, {hi}) ;")
        lines.append("   Sample ;")
    driver = workdir / "Driver.mod"
    driver.write_text(M2_DRIVER.format(name=name, tmax=LANGUAGES["m2"].float_literal(tmax),
                                       samples="\n".join(lines)))
    run([gm2, "-fiso", "-fcpp", "-g", "-Wall", "-Werror", "-c", out.name, "-o", f"{name}.o"],
        cwd=workdir)
    run([gm2, "-fiso", "-g", "Driver.mod", f"{name}.o", str(runtime_obj), "-o", "driver",
         *gm2_link_flags(gm2)], cwd=workdir)
    return run([str(workdir / "driver")], cwd=workdir).stdout.splitlines()


def parse_m2(line: str) -> tuple[int, list[float], float | None]:
    """(variant chosen, coefficients up to the degree used, first root or None)."""
    left, right = line.split(" | ")
    fields = left.split()
    degree = int(fields[1])
    coefs = [from_halves(fields[2 + 2 * i], fields[3 + 2 * i]) for i in range(degree + 1)]
    assert len(fields) == 2 + 2 * (degree + 1)
    status, lo, hi = right.split()
    return int(fields[0]), coefs, (from_halves(lo, hi) if status == "1" else None)


def test_m2_module_matches_oracle(equation, tmp_path: Path, c_runtime_object: Path) -> None:
    path, (spec, poly), exact = equation
    lines = build_m2(path, tmp_path, [e.params for e in exact], c_runtime_object)
    meta = lines[0].split()
    assert int(meta[0]) == len(poly.parameters) and int(meta[1]) == poly.degree
    assert tuple(meta[2:]) == poly.parameters
    variants = family(poly)
    assert lines[1:1 + len(variants)] == [v.label for v in variants]
    lines = lines[1 + len(variants):]
    assert len(lines) == len(exact)
    for i, (line, e) in enumerate(zip(lines, exact)):
        chosen, coefs, root = parse_m2(line)
        assert chosen == len(variants) - 1  # random parameters are never exactly zero
        assert len(coefs) == poly.degree + 1
        check_sample(e, coefs, root, f"Modula-2 sample {i}")


# ---------------------------------------------------------------------------------------------
# Rust: one crate with every equation, built once
# ---------------------------------------------------------------------------------------------

RUST_MAIN = """\
// Test driver: lines "NAME TMAX p0 p1 ..." (f64 bit patterns in hex) on stdin; for each, prints
// "variant degree c0 .. cn | 1 t" or "... | 0", bit patterns in hex. "meta NAME" prints NAME,
// K, N, PARAMS, STRATEGY.
{mods}

use std::io::{{BufRead, Write}};

fn parse(s: &str) -> f64 {{
    f64::from_bits(u64::from_str_radix(s, 16).expect("hex bit pattern"))
}}

fn sample<const K: usize, const M: usize>(
    p: &[f64],
    tmax: f64,
    coefficients_degree: fn(&[f64; K]) -> (usize, [f64; M]),
    coefficients: fn(&[f64; K]) -> [f64; M],
    first_root: fn(&[f64; K], f64) -> Option<f64>,
    variant: (fn(&[f64; K]) -> usize, usize),
) -> String {{
    let p: [f64; K] = p.try_into().expect("parameter count");
    let chosen = variant.0(&p);
    assert!(chosen < variant.1);
    let (degree, c) = coefficients_degree(&p);
    assert_eq!(coefficients(&p), c);
    let mut out = format!("{{chosen}} {{degree}}");
    for x in &c[..=degree] {{
        out += &format!(" {{:016x}}", x.to_bits());
    }}
    match first_root(&p, tmax) {{
        Some(t) => out + &format!(" | 1 {{:016x}}", t.to_bits()),
        None => out + " | 0",
    }}
}}

fn main() {{
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    for line in std::io::stdin().lock().lines() {{
        let line = line.expect("stdin");
        let mut words = line.split_whitespace();
        let name = words.next().expect("a name");
        if name == "meta" {{
            let text = match words.next().expect("a name") {{
{metas}
                other => panic!("unknown equation {{other}}"),
            }};
            writeln!(out, "{{text}}").expect("stdout");
            continue;
        }}
        let tmax = parse(words.next().expect("tmax"));
        let p: Vec<f64> = words.map(parse).collect();
        let text = match name {{
{samples}
            other => panic!("unknown equation {{other}}"),
        }};
        writeln!(out, "{{text}}").expect("stdout");
    }}
}}
"""


@pytest.fixture(scope="session")
def rust_crate(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    """(crate folder, built binary) for all shipped equations plus the keyword equation."""
    cargo = cargo_exe()
    crate = tmp_path_factory.mktemp("rust-crate")
    src = crate / "src"
    src.mkdir()
    keywords = crate / "keywords.mxm"
    keywords.write_text(KEYWORDS_MXM)
    names = []
    for mxm in [*EQUATIONS, keywords]:
        spec, poly = load(str(mxm))
        name = module_name(spec)
        out = src / f"{name}.rs"
        out.write_text(generate(spec, poly, LANGUAGES["rust"], "module", str(out)).text)
        names.append(name)
    (crate / "Cargo.toml").write_text(
        '[package]\nname = "max2code-generated-test"\nversion = "0.0.0"\nedition = "2021"\n'
        'publish = false\n\n[dependencies]\n'
        f'max2code-runtime = {{ path = "{RUST_RUNTIME.as_posix()}" }}\n')
    (src / "main.rs").write_text(RUST_MAIN.format(
        mods="\n".join(f"mod {n};" for n in names),
        metas="\n".join(f'                "{n}" => format!("{{}} {{}} {{}} {{}} {{}}", {n}::NAME, '
                        f'{n}::PARAMS.len(), {n}::DEGREE, {n}::PARAMS.join(" "), '
                        f'{n}::STRATEGY),' for n in names),
        samples="\n".join(f'            "{n}" => sample(&p, tmax, {n}::coefficients_degree, '
                          f'{n}::coefficients, {n}::first_root, '
                          f'({n}::variant, {n}::VARIANTS.len())),' for n in names)))
    env = {**os.environ, "CARGO_TARGET_DIR": str(CARGO_TARGET), "RUSTFLAGS": "-D warnings"}
    run([cargo, "build", "--release", "--quiet"], cwd=crate, env=env)
    binary = CARGO_TARGET / "release" / "max2code-generated-test"
    return crate, binary


def run_rust(binary: Path, lines: list[str]) -> list[str]:
    return run([str(binary)], input="\n".join(lines) + "\n").stdout.splitlines()


def rust_line(name: str, tmax: float, params: tuple[float, ...]) -> str:
    return " ".join([name, *(f"{struct.unpack('<Q', struct.pack('<d', v))[0]:016x}"
                             for v in (tmax, *params))])


def parse_rust(line: str) -> tuple[int, list[float], float | None]:
    """(variant chosen, coefficients up to the degree used, first root or None)."""
    left, right = line.split(" | ")
    fields = left.split()
    coefs = [struct.unpack("<d", struct.pack("<Q", int(x, 16)))[0] for x in fields[2:]]
    assert int(fields[1]) == len(coefs) - 1
    parts = right.split()
    root = struct.unpack("<d", struct.pack("<Q", int(parts[1], 16)))[0] if parts[0] == "1" else None
    return int(fields[0]), coefs, root


def test_rust_module_matches_oracle(equation, rust_crate: tuple[Path, Path]) -> None:
    path, (spec, poly), exact = equation
    name = module_name(spec)
    _, binary = rust_crate
    out = run_rust(binary, [f"meta {name}"] + [rust_line(name, TMAX, e.params) for e in exact])
    meta = out[0].split()
    assert meta[0] == name
    assert int(meta[1]) == len(poly.parameters) and int(meta[2]) == poly.degree
    assert tuple(meta[3:-1]) == poly.parameters
    assert len(out) == 1 + len(exact)
    for i, (line, e) in enumerate(zip(out[1:], exact)):
        chosen, coefs, root = parse_rust(line)
        assert chosen == len(family(poly)) - 1  # random parameters are never exactly zero
        assert len(coefs) == poly.degree + 1
        check_sample(e, coefs, root, f"Rust sample {i}")


def test_rust_modules_are_clippy_clean(rust_crate: tuple[Path, Path]) -> None:
    crate, _ = rust_crate
    env = {**os.environ, "CARGO_TARGET_DIR": str(CARGO_TARGET)}
    proc = subprocess.run([cargo_exe(), "clippy", "--quiet", "--", "-D", "warnings"], cwd=crate,
                          env=env, capture_output=True, text=True)
    if proc.returncode != 0 and "no such command" in proc.stderr:
        if os.environ.get("CI"):
            pytest.fail("cargo clippy is not installed -- required in CI")
        pytest.skip("cargo clippy is not installed (rustup component add clippy)")
    assert proc.returncode == 0, proc.stderr


def test_rust_module_can_be_included(rust_crate: tuple[Path, Path], tmp_path: Path) -> None:
    """The other documented use: `include!("NAME.rs")` inside a module of one's own."""
    crate, _ = rust_crate
    src = tmp_path / "src"
    src.mkdir()
    shutil.copy(crate / "src" / "circles_accel.rs", src)
    (src / "main.rs").write_text(
        '#[allow(dead_code)] // this program does not use NAME; a binary warns about that\n'
        'mod collide {\n    include!("circles_accel.rs");\n}\n\nfn main() {\n'
        '    let mut p = [0.0; collide::PARAMS.len()];\n'
        '    p[2] = 1.0; // vx1\n    p[6] = 0.5; // r1\n    p[7] = 3.0; // x2\n'
        '    p[13] = 0.5; // r2\n'
        '    assert_eq!(collide::DEGREE, 4);\n'
        '    println!("{:?} {:?}", collide::coefficients(&p), collide::first_root(&p, 10.0));\n'
        '}\n')
    (tmp_path / "Cargo.toml").write_text(  # its own name: the session's binary stays in place
        (crate / "Cargo.toml").read_text().replace("max2code-generated-test",
                                                   "max2code-include-test"))
    env = {**os.environ, "CARGO_TARGET_DIR": str(CARGO_TARGET), "RUSTFLAGS": "-D warnings"}
    out = run([cargo_exe(), "run", "--release", "--quiet"], cwd=tmp_path, env=env).stdout
    assert out.strip() == "[8.0, -6.0, 1.0, 0.0, 0.0] Some(2.0)"


# ---------------------------------------------------------------------------------------------
# Every variant: parameters of its roles exactly zero (as tests/test_variants.py does for C/Python)
# ---------------------------------------------------------------------------------------------

PER_VARIANT = 12


@pytest.fixture(scope="module", params=EQUATIONS, ids=lambda p: p.stem)
def variant_cases(request: pytest.FixtureRequest, maxima_exe: str):
    """(spec, poly, [(variant index, params)], exact per sample)."""
    path = request.param
    spec, poly = load(str(path))
    samples = []
    for v in family(poly):
        seed = zlib.crc32(path.name.encode()) + v.index
        for params in random_samples(poly.parameters, PER_VARIANT, seed=seed):
            samples.append((v.index, tuple(0.0 if n in v.zeros else x
                                           for n, x in zip(poly.parameters, params))))
    exact = exact_coefficients(path, poly.parameters, [p for _, p in samples])
    return spec, poly, samples, exact


def check_variant(label: str, k: int, chosen: int, coefs: list[float], root: float | None,
                  exact: Exact) -> None:
    assert chosen == k, f"{label}: the dispatcher chose variant {chosen} for variant {k}"
    assert len(coefs) == len(exact.coefficients), (
        f"{label}: degree {len(coefs) - 1}, exact {len(exact.coefficients) - 1}")
    check_sample(exact, coefs, root, label)


def test_m2_variants(variant_cases, tmp_path: Path, c_runtime_object: Path) -> None:
    spec, poly, samples, exact = variant_cases
    lines = build_m2(Path(spec.path), tmp_path, [p for _, p in samples], c_runtime_object)
    lines = lines[1 + len(family(poly)):]
    assert len(lines) == len(samples)
    for (k, _), line, e in zip(samples, lines, exact):
        check_variant(f"Modula-2 v{k}", k, *parse_m2(line), e)


def test_rust_variants(variant_cases, rust_crate: tuple[Path, Path]) -> None:
    spec, poly, samples, exact = variant_cases
    name = module_name(spec)
    out = run_rust(rust_crate[1], [rust_line(name, TMAX, p) for _, p in samples])
    assert len(out) == len(samples)
    for (k, _), line, e in zip(samples, out, exact):
        check_variant(f"Rust v{k}", k, *parse_rust(line), e)


# ---------------------------------------------------------------------------------------------
# Keywords as parameter names, in all four languages
# ---------------------------------------------------------------------------------------------

@pytest.fixture
def keywords_mxm(tmp_path: Path) -> Path:
    path = tmp_path / "keywords.mxm"
    path.write_text(KEYWORDS_MXM)
    return path


def assert_close(got: list[float], want: list[float], label: str) -> None:
    assert len(got) == len(want), label
    for k, (g, w) in enumerate(zip(got, want)):
        assert abs(g - w) <= 1e-15 * max(1.0, abs(w)), f"{label}: c[{k}] = {g!r}, want {w!r}"


def test_keywords_c(keywords_mxm: Path, tmp_path: Path, c_runtime_object: Path) -> None:
    gcc = require("gcc")
    spec, poly = load(str(keywords_mxm))
    header = tmp_path / "keywords.h"
    header.write_text(generate(spec, poly, LANGUAGES["c"], "module", str(header)).text)
    (tmp_path / "main.c").write_text(
        '#include <stdio.h>\n#include "keywords.h"\nint main(void) {\n'
        f'    const double p[keywords_NPARAMS] = {{{", ".join(map(repr, KEYWORD_PARAMS))}}};\n'
        '    double c[keywords_DEGREE + 1];\n    int n = keywords_coefficients(p, c);\n'
        '    for (int i = 0; i <= n; i++) printf("%a\\n", c[i]);\n    return 0;\n}\n')
    run([gcc, "-std=c11", "-Wall", "-Wextra", "-Werror", "-pedantic", f"-I{C_RUNTIME}",
         f"-I{tmp_path}", str(tmp_path / "main.c"), str(c_runtime_object), "-o",
         str(tmp_path / "kw"), "-lgsl", "-lgslcblas", "-lm"])
    out = run([str(tmp_path / "kw")]).stdout.split()
    assert_close([float.fromhex(x) for x in out], keyword_coefficients(KEYWORD_PARAMS), "C")


def test_keywords_python(keywords_mxm: Path, tmp_path: Path) -> None:
    spec, poly = load(str(keywords_mxm))
    out = tmp_path / "keywords_py.py"
    out.write_text(generate(spec, poly, LANGUAGES["python"], "module", str(out)).text)
    module_spec = importlib.util.spec_from_file_location("keywords_py", out)
    assert module_spec and module_spec.loader
    module = importlib.util.module_from_spec(module_spec)
    module_spec.loader.exec_module(module)
    assert tuple(module.PARAMS) == ("type", "match", "self", "VAR", "TYPE", "int", "char", "BEGIN")
    assert_close(module.coefficients(KEYWORD_PARAMS), keyword_coefficients(KEYWORD_PARAMS),
                 "Python")


def test_keywords_m2(keywords_mxm: Path, tmp_path: Path, c_runtime_object: Path) -> None:
    lines = build_m2(keywords_mxm, tmp_path, [KEYWORD_PARAMS], c_runtime_object)
    assert lines[0].split()[2:] == ["type", "match", "self", "VAR", "TYPE", "int", "char", "BEGIN"]
    text = (tmp_path / "keywords.mod").read_text()
    for mangled in ("VAR_ := m2c_p[3]", "TYPE_ := m2c_p[4]", "BEGIN_ := m2c_p[7]",
                    "type := m2c_p[0]"):
        assert mangled in text
    _, coefs, _ = parse_m2(lines[-1])
    assert_close(coefs, keyword_coefficients(KEYWORD_PARAMS), "Modula-2")


def test_keywords_rust(rust_crate: tuple[Path, Path]) -> None:
    crate, binary = rust_crate
    text = (crate / "src" / "keywords.rs").read_text()
    assert "let [r#type, r#match, self_, VAR, TYPE, int, char_, BEGIN] = *m2c_p;" in text
    out = run_rust(binary, ["meta keywords", rust_line("keywords", TMAX, KEYWORD_PARAMS)])
    assert out[0].split()[3:-1] == ["type", "match", "self", "VAR", "TYPE", "int", "char", "BEGIN"]
    _, coefs, _ = parse_rust(out[1])
    assert_close(coefs, keyword_coefficients(KEYWORD_PARAMS), "Rust")


# ---------------------------------------------------------------------------------------------
# Determinism: the same input gives byte-identical output, companions included
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("lang", ["m2", "rust"])
@pytest.mark.parametrize("mxm", EQUATIONS, ids=lambda p: p.stem)
def test_output_is_deterministic(lang: str, mxm: Path, maxima_exe: str) -> None:
    out = f"out{LANGUAGES[lang].extension}"
    first = generate(*load(str(mxm)), LANGUAGES[lang], "module", out)
    again = generate(*load(str(mxm)), LANGUAGES[lang], "module", out)
    assert (first.text, first.companions) == (again.text, again.companions)


# ---------------------------------------------------------------------------------------------
# The paper's use: a Modula-2 fragment pasted into a procedure
# ---------------------------------------------------------------------------------------------

def test_m2_fragment_compiles_as_the_paper_used_it(tmp_path: Path) -> None:
    gm2 = require("gm2")
    mxm, _ = corrected_paper_point_line(tmp_path)
    spec, poly = load(str(mxm))
    fragment = tmp_path / "fragment.inc"
    result = generate(spec, poly, LANGUAGES["m2"], "fragment", str(fragment))
    assert result.companions == ()
    fragment.write_text(result.text + "\n")
    body = result.text
    assert "VAR\n    t: REAL ;" in body and "t := findSmallestPositiveRoot(coef)" in body
    assert [ln.split(" :=")[0] for ln in body.splitlines() if ln.startswith("coef[")] == [
        f"coef[{k}]" for k in range(5)]
    assert all(ln.endswith(" ;") for ln in body.splitlines() if ln.startswith("coef["))
    params = ", ".join(poly.parameters)
    (tmp_path / "Paper.mod").write_text(
        "MODULE Paper ;\n\nVAR\n   " + params + ": REAL ;\n\n"
        "PROCEDURE findSmallestPositiveRoot (VAR c: ARRAY OF REAL) : REAL ;\n"
        "BEGIN\n   RETURN c[0]\nEND findSmallestPositiveRoot ;\n\n"
        "PROCEDURE Predict ;\n#include \"fragment.inc\"\nEND Predict ;\n\n"
        "BEGIN\n   Predict\nEND Paper.\n")
    run([gm2, "-fiso", "-fcpp", "-g", "-Wall", "-c", "Paper.mod", "-o", "Paper.o"], cwd=tmp_path)


# ---------------------------------------------------------------------------------------------
# Printer rules (no tools needed)
# ---------------------------------------------------------------------------------------------

def test_printer_signs_literals_and_constants() -> None:
    from fractions import Fraction

    from max2code.codegen.expr import Add, Div, Float, Mul, Neg, Num, Pow, Sym

    a, b, c = Sym("a"), Sym("b"), Sym("c")
    # Modula-2 allows a sign only at the start of an expression; Rust would accept more, but
    # clippy rejects `--x` and `a + -b` reads badly: both print signed operands the same way.
    cases = [
        (Mul((a, Neg(b))), "-a*b"),
        (Add((a, Mul((Num(Fraction(-2)), b)))), "a - 2.0*b"),
        (Div(a, Neg(b)), "a/(-b)"),
        (Pow(Neg(a), Num(Fraction(2))), "(-a)*(-a)"),
        (Add((a, Neg(Neg(b)))), "a - (-b)"),
        (Neg(Add((a, b))), "-(a + b)"),
        (Mul((a, Add((Neg(b), c)))), "a*(-b + c)"),
        (Neg(Mul((Num(Fraction(-2)), a))), "-(-2.0*a)"),
        (Add((a, Neg(Add((b, c))))), "a - (b + c)"),
    ]
    for lang in ("m2", "rust"):
        for e, want in cases:
            assert LANGUAGES[lang].expr(e) == want, (lang, e)
    m2, rust = LANGUAGES["m2"], LANGUAGES["rust"]
    assert m2.expr(Float("1e-5")) == "1.0E-05"
    assert m2.expr(Float("-1.5e16")) == "-1.5E+16"
    assert m2.expr(Num(Fraction(3))) == "3.0"
    assert rust.expr(Sym("%pi")) == "std::f64::consts::PI"  # clippy: approx_constant
    assert rust.expr(Float("1e-5")) == "1e-05"
    assert m2.expr(Pow(a, Num(Fraction(1, 2)))) == "RealMath.sqrt(a)"
    assert rust.expr(Pow(a, b)) == "f64::powf(a, b)"


def test_identifiers() -> None:
    """(max2code/codegen/names.py decides; tests/test_names.py tests it on every name.)"""
    m2, rust = LANGUAGES["m2"], LANGUAGES["rust"]
    names = ("type", "match", "self", "VAR", "TYPE", "int", "char", "BEGIN", "MOD", "DIV", "REAL")
    where = Pos("k.mxm", 1, 1)
    def idents(names: tuple[str, ...], lang) -> list[str]:
        naming = choose(names, lang, "k", where)
        return [naming.idents[n] for n in names]

    assert idents(names, m2) == [
        "type", "match", "self", "VAR_", "TYPE_", "int", "char", "BEGIN_", "MOD_", "DIV_", "REAL_"]
    assert idents(names, rust) == [
        "r#type", "r#match", "self_", "VAR", "TYPE", "int", "char_", "BEGIN", "MOD", "DIV", "REAL"]
    names = ("fn", "in", "loop", "mod", "ref", "move", "Self")
    assert idents(names, rust) == [
        "r#fn", "r#in", "r#loop", "r#mod", "r#ref", "r#move", "Self_"]
    assert rust.lint_allows(["x1", "vx_1"]) == ""
    assert "non_snake_case" in rust.lint_allows(["x1", "TYPE"])


def test_m2_binding_of_the_c_runtime(tmp_path: Path, c_runtime_object: Path) -> None:
    """runtime/m2/Max2codeRoots.def: every procedure and constant, called from Modula-2."""
    gm2 = require("gm2")
    shutil.copy(M2_RUNTIME / "Max2codeRoots.def", tmp_path)
    (tmp_path / "Binding.mod").write_text("""\
MODULE Binding ;
FROM STextIO IMPORT WriteString, WriteLn ;
FROM SWholeIO IMPORT WriteInt ;
FROM Max2codeRoots IMPORT MaxDegree, MethodInterval, MethodIntervalNoGraze, MethodGsl,
   MethodClosed, m2c_first_root, m2c_first_root_method, m2c_first_root_ex ;
VAR
   c: ARRAY [0..MaxDegree] OF REAL ;
   t: REAL ;
   graze: INTEGER ;

PROCEDURE Show (status: INTEGER; expect: REAL) ;
BEGIN
   WriteInt(status, 0) ;
   IF (status = 1) AND (ABS(t - expect) <= 1.0E-12) THEN WriteString(" ok") END ;
   WriteLn
END Show ;

BEGIN
   (* (t - 2)^2: a graze at 2 *)
   c[0] := 4.0 ; c[1] := -4.0 ; c[2] := 1.0 ;
   t := 0.0 ; Show(m2c_first_root(c, 2, 10.0, t), 2.0) ;
   t := 0.0 ; graze := 7 ;
   Show(m2c_first_root_ex(c, 2, 10.0, t, MethodInterval, graze), 2.0) ;
   WriteInt(graze, 0) ; WriteLn ;
   (* (t - 1)(t - 3)(t - 4) = t^3 - 8t^2 + 19t - 12 *)
   c[0] := -12.0 ; c[1] := 19.0 ; c[2] := -8.0 ; c[3] := 1.0 ;
   t := 0.0 ; Show(m2c_first_root_method(c, 3, 10.0, t, MethodClosed), 1.0) ;
   t := 0.0 ; Show(m2c_first_root_method(c, 3, 10.0, t, MethodGsl), 1.0) ;
   t := 0.0 ; Show(m2c_first_root_method(c, 3, 10.0, t, MethodIntervalNoGraze), 1.0) ;
   t := 0.0 ; Show(m2c_first_root_method(c, 3, 0.5, t, MethodInterval), 1.0) ;
   t := 0.0 ; Show(m2c_first_root(c, 3, -1.0, t), 1.0)
END Binding.
""")
    run([gm2, "-fiso", "-g", "-Wall", "-Werror", "Binding.mod", str(c_runtime_object), "-o",
         "binding", *gm2_link_flags(gm2)], cwd=tmp_path)
    out = run([str(tmp_path / "binding")]).stdout.split("\n")
    # gm2's ISO WriteInt writes a sign; the third line is the graze flag.
    assert out[:8] == ["+1 ok", "+1 ok", "+1", "+1 ok", "+1 ok", "+1 ok", "+0", "-1"]
