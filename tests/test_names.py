"""Every name compiles: no generated identifier can clash with a user's parameter, in any
language, and fragments keep the user's names.

* The naming rules (max2code/codegen/names.py, each language's lists) without any tool: ordinary names
  are kept, keywords escaped, fragments touch keywords only (with a warning), renamed
  identifiers are unique.
* The lists are complete: every object-like macro gcc defines after the C library's headers and
  the runtime's is reserved in C (asked of gcc itself), the running Python has no builtin the
  Python list lacks, and every identifier in a generated module of each language is either
  reserved there or a parameter's own (so a template cannot start using a name unnoticed).
* A corpus of names (ordinary ones like p, c, i, k, n, t0, tmax, degree, result, variant, x;
  every keyword and predeclared name of every target language; a sample of gcc's macros; every
  identifier our generated modules use) as the parameters of real equations, built in all four
  languages by `max2code check` and compared with the oracle.
"""

from __future__ import annotations

import builtins
import io
import re
import shutil
import subprocess
import tokenize
from pathlib import Path

import pytest

from conftest import ROOT, require

from max2code.commands import check as chk
from max2code.maxima import names as maxima_names
from max2code.diagnostics import Pos
from max2code.codegen.emit import context
from max2code.codegen.generate import generate, load
from max2code.languages import LANGUAGES
from max2code.languages.m2.printer import M2_FORMALS
from max2code.languages.python.printer import PY_PREDECLARED
from max2code.languages.rust.printer import RUST_FUNCTIONS
from max2code.codegen.names import choose

ORDINARY = "p c i k n t0 tmax degree result variant x q t1 tmin value c0 c1".split()
# Names Maxima does not read as plain symbols (its keywords, constants and option variables
# that evaluate to something else): they cannot be parameters of an equation at all.
MAXIMA_CANNOT = {"_", "and", "do", "else", "false", "float", "for", "from", "help", "if", "next",
                 "not", "or", "stderr", "stdin", "stdout", "true", "while", "then", "thru",
                 "step", "unless", "in",
                 "t"}  # the equation's variable
WHERE = Pos("x.mxm", 1, 1)
C_HEADERS = ("assert complex ctype errno fenv float inttypes iso646 limits locale math setjmp "
             "signal stdalign stdarg stdatomic stdbool stddef stdint stdio stdlib stdnoreturn "
             "string tgmath threads time uchar wchar wctype").split()


# ---------------------------------------------------------------------------------------------
# The rules
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("lang", sorted(LANGUAGES))
def test_ordinary_names_are_kept(lang: str) -> None:
    """Kept wherever the user sees them: fragments, and the fields of C, Rust and Modula-2
    (Python's modules bind them as locals only, and may rename `variant` there unseen)."""
    for module in ("circles", None):
        naming = choose(tuple(ORDINARY), LANGUAGES[lang], module, WHERE)
        if module is None or LANGUAGES[lang].shows_names:
            assert naming.idents == {n: n for n in ORDINARY}, (lang, module)
        assert naming.warnings == ()


def test_fragments_rename_keywords_only_and_say_so() -> None:
    py = choose(("p", "lambda", "math", "len", "c"), LANGUAGES["python"], None, WHERE)
    assert py.idents == {"p": "p", "lambda": "lambda_", "math": "math", "len": "len", "c": "c"}
    assert [str(w) for w in py.warnings] == [
        "x.mxm:1:1: warning: parameter 'lambda' is written 'lambda_' in the Python fragment: "
        "'lambda' is a Python keyword"]
    rust = choose(("type", "self", "None", "p"), LANGUAGES["rust"], None, WHERE)
    assert rust.idents == {"type": "r#type", "self": "self_", "None": "None", "p": "p"}
    assert len(rust.warnings) == 1 and "'self'" in str(rust.warnings[0])
    c = choose(("int", "NULL", "m2c_x"), LANGUAGES["c"], None, WHERE)
    assert c.idents == {"int": "int_", "NULL": "NULL", "m2c_x": "m2c_x"}
    m2 = choose(("VAR", "REAL", "c"), LANGUAGES["m2"], None, WHERE)
    assert m2.idents == {"VAR": "VAR_", "REAL": "REAL", "c": "c"}


def test_modules_rename_what_the_language_reserves() -> None:
    c = choose(("int", "NULL", "m2c_p", "circles_DEGREE", "M2C_MAX_DEGREE", "INFINITY", "x"),
               LANGUAGES["c"], "circles", WHERE)
    assert c.idents == {"int": "int_", "NULL": "NULL_", "m2c_p": "p_m2c_p",
                        "circles_DEGREE": "p_circles_DEGREE",
                        "M2C_MAX_DEGREE": "p_M2C_MAX_DEGREE", "INFINITY": "INFINITY_", "x": "x"}
    assert [w.message for w in c.warnings][0] == (
        "parameter 'int' is written 'int_' in the C module: 'int' is a C keyword")
    rust = choose(("None", "Some", "DEGREE", "type", "Vec", "variant"), LANGUAGES["rust"], "m",
                  WHERE)
    assert rust.idents == {"None": "None_", "Some": "Some_", "DEGREE": "DEGREE_",
                           "type": "r#type", "Vec": "Vec", "variant": "variant"}
    py = choose(("lambda", "len", "math", "m2c_p", "PARAMS", "p"), LANGUAGES["python"], "m", WHERE)
    assert py.idents == {"lambda": "lambda_", "len": "len_", "math": "math_",
                         "m2c_p": "p_m2c_p", "PARAMS": "PARAMS_", "p": "p"}
    assert py.warnings == ()  # Python modules show no parameter identifier to their users


def test_renamed_identifiers_never_collide() -> None:
    params = ("int", "int_", "int__", "NULL", "NULL_", "a%b", "a_b")
    naming = choose(params, LANGUAGES["c"], "m", WHERE)
    idents = list(naming.idents.values())
    assert len(set(idents)) == len(idents)
    assert naming.idents["int_"] == "int_" and naming.idents["int__"] == "p_int"
    assert naming.idents["int"] == "int_2" and naming.idents["NULL"] == "NULL_2"
    assert naming.idents["a%b"] == "a_b" and naming.idents["a_b"] == "a_b_2"
    assert all(LANGUAGES["c"].reserved(i, "m") is None for i in idents)


# ---------------------------------------------------------------------------------------------
# The lists are complete
# ---------------------------------------------------------------------------------------------

def gcc_macros(tmp_path: Path) -> set[str]:
    """Every object-like macro after all the C library's headers and the runtime's, in the
    strict and the GNU modes."""
    gcc = require("gcc")
    source = tmp_path / "all.c"
    source.write_text("".join(f"#include <{h}.h>\n" for h in C_HEADERS)
                      + '#include "max2code_roots.h"\n')
    names: set[str] = set()
    for flags in (["-std=c11"], ["-std=gnu11", "-D_GNU_SOURCE"], ["-std=gnu17"]):
        out = subprocess.run([gcc, *flags, "-dM", "-E", f"-I{ROOT / 'runtime' / 'c'}",
                              str(source)], capture_output=True, text=True, check=True).stdout
        names |= {m.group(1) for m in re.finditer(r"^#define (\w+)(?![\w(])", out, re.M)}
    assert len(names) > 1000
    return names


def test_every_c_macro_is_reserved(tmp_path: Path) -> None:
    c = LANGUAGES["c"]
    free = sorted(n for n in gcc_macros(tmp_path) if c.reserved(n, "m") is None)
    assert free == [], f"C macros a parameter could be named: {free[:20]}"


def test_every_macro_of_gm2s_preprocessor_is_reserved() -> None:
    """gm2 -fcpp runs cc1 -E -traditional-cpp -lang-asm: its predefined macros reach Modula-2."""
    cpp = require("cpp")
    out = subprocess.run([cpp, "-traditional-cpp", "-dM"], input="", capture_output=True,
                         text=True, check=True).stdout
    names = {m.group(1) for m in re.finditer(r"^#define (\w+)", out, re.M)}
    assert "linux" in names or "unix" in names
    m2 = LANGUAGES["m2"]
    assert [n for n in names if m2.reserved(n, "m") is None] == []


def test_every_python_builtin_is_listed() -> None:
    assert set(dir(builtins)) <= PY_PREDECLARED


def identifiers(lang: str, text: str) -> set[str]:
    """The identifiers a generated file uses as names in scope (not members after `.` or
    `::`, not inside comments, strings, attributes or line directives)."""
    if lang == "python":
        out, previous = set(), ""
        for tok in tokenize.generate_tokens(io.StringIO(text).readline):
            if tok.type == tokenize.NAME and previous != ".":
                out.add(tok.string)
            previous = tok.string
        return out
    if lang == "m2":
        text = re.sub(r"\(\*.*?\*\)", " ", text, flags=re.S)
    else:
        text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
        text = re.sub(r"//[^\n]*", " ", text)
    text = re.sub(r'"(\\.|[^"\\])*"', " ", text)
    text = re.sub(r"^#(line|include)[^\n]*", " ", text, flags=re.M)
    text = re.sub(r"^#\s*(define|ifndef|endif)\b", " ", text, flags=re.M)  # keep the names
    text = re.sub(r"#\[[^\]]*\]", " ", text)  # Rust attributes
    return {m.group(2) for m in re.finditer(r"(\.|::)?\b((?:r#)?[A-Za-z_]\w*)", text)
            if not m.group(1)}


@pytest.mark.parametrize("lang", sorted(LANGUAGES))
def test_every_identifier_of_a_module_is_reserved(lang: str, tmp_path: Path,
                                                  maxima_exe: str) -> None:
    spec, poly = load(str(names_equation(tmp_path, "drift", ORDINARY, True)))
    result = generate(spec, poly, LANGUAGES[lang], "module", f"drift{LANGUAGES[lang].extension}")
    ctx = context(spec, poly, LANGUAGES[lang])
    own = {p.ident for p in ctx.params}
    used = set()
    for text in [result.text, *(t for _, t in result.companions)]:
        used |= identifiers(lang, text)
    shadowable = {"rust": RUST_FUNCTIONS, "m2": M2_FORMALS}.get(lang, frozenset())
    free = sorted(i for i in used - own - shadowable
                  if LANGUAGES[lang].reserved(i, "drift") is None)
    assert free == [], f"{lang}: identifiers a parameter could clash with: {free}"
    assert own & used == own  # the parameters are there, under the identifiers chosen


# ---------------------------------------------------------------------------------------------
# The corpus, compiled and run in all four languages
# ---------------------------------------------------------------------------------------------

def names_equation(folder: Path, name: str, params: list[str], with_role: bool) -> Path:
    """An equation using every one of `params`: p_i multiplies t^(i mod 3), plus the square of
    (p_0 - p_1 t); with a role zeroing every t^2 factor, so that the variant selection binds
    names too."""
    terms = [f"{p}*t^{i % 3}" for i, p in enumerate(params)]
    body = " + ".join(terms) + f" - ({params[0]} - {params[1]}*t)^2"
    quadratic = [p for i, p in enumerate(params) if i % 3 == 2] + [params[1]]
    lines = [f"function {name}", "parameters " + ", ".join(params)]
    if with_role:
        lines.append("role flat = " + ", ".join(quadratic))
    path = folder / f"{name}.mxm"
    path.write_text("\n".join(lines + ["begin", body + ";", "end"]) + "\n")
    return path


def corpus_names(tmp_path: Path) -> list[str]:
    names: set[str] = set(ORDINARY)
    for lang in LANGUAGES.values():
        names |= lang.keywords | lang.predeclared | lang.generated("names0")
    names |= RUST_FUNCTIONS | M2_FORMALS
    names |= {"Vec", "String", "Box", "Result", "Iterator", "drop", "vec", "println", "u8"}
    names |= {"NULL", "INFINITY", "NAN", "M2C_MAX_DEGREE", "M2C_METHOD_GSL", "MAX2CODE_ROOTS_H",
              "EOF", "I", "errno", "linux", "unix", "REAL", "TRUE", "ABS", "INC"}
    # Names shaped like the generated modules' own identifiers, read from their text.
    spec, poly = load(str(names_equation(tmp_path, "names0", ORDINARY, True)))
    for name, lang in LANGUAGES.items():
        result = generate(spec, poly, lang, "module", f"names0{lang.extension}")
        for text in [result.text, *(t for _, t in result.companions)]:
            names |= {i.removeprefix("r#") for i in identifiers(name, text)}
    macros = sorted(gcc_macros(tmp_path))
    names |= set(macros[::25])  # a sample; test_every_c_macro_is_reserved covers them all
    return sorted(n for n in names if re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", n)
                  and n not in MAXIMA_CANNOT and n not in maxima_names.variables()
                  and "__" not in n)


def test_the_names_corpus_compiles_and_agrees_with_the_oracle(tmp_path: Path,
                                                              maxima_exe: str) -> None:
    for tool in ("gcc", "gm2"):
        require(tool)
    names = corpus_names(tmp_path)
    assert len(names) > 600 and set(ORDINARY) <= set(names)
    assert {"NULL", "Some", "None", "lambda", "REAL", "names0_DEGREE", "m2c_p"} <= set(names)
    chunk = 120
    folder = tmp_path / "corpus"
    folder.mkdir()
    equations = []
    for k in range(0, len(names), chunk):
        # Every module is named names0 .. namesN, and names0's identifiers are in the corpus.
        equations.append(names_equation(folder, f"names{k // chunk}", names[k:k + chunk], True))
    for mxm in equations:
        spec, poly = load(str(mxm))
        declared = spec.parameter_order
        assert poly.parameters == declared  # nothing renamed or lost on the way through Maxima
    report = chk.check(equations, langs=["c", "python", "m2", "rust"],
                       build_dir=ROOT / "build" / "check")
    assert report.ok, report.text()
    assert {(r.equation, r.lang) for r in report.rows} == {
        (m.stem, lang) for m in equations for lang in ("c", "python", "m2", "rust")}
    assert {r.family for r in report.rows} >= {"generic", "variant"}


# ---------------------------------------------------------------------------------------------
# Fragments keep the user's names
# ---------------------------------------------------------------------------------------------

FRAGMENT_MXM = """\
function frag
parameters p, c, lambda, type, int, x
initialise python {
a = [0.0] * 3
}
initialise rust { let mut a = [0.0f64; 3]; }
initialise c { double a[3]; }
term 0 python { a[0] = }
term 1 python { a[1] = }
term 2 python { a[2] = }
term 0 rust { a[0] = }
term 1 rust { a[1] = }
term 2 rust { a[2] = }
term 0 c { a[0] = }
term 1 c { a[1] = }
term 2 c { a[2] = }
begin
p*t^2 - c*t + lambda - x*type*int;
end
"""
VALUES = {"p": 1.5, "c": -2.25, "lambda": 0.75, "type": 3.0, "int": -0.5, "x": 1.25}
WANT = [0.75 - 1.25 * 3.0 * -0.5, 2.25, 1.5]  # lambda - x type int, -c, p


@pytest.fixture
def fragment_spec(tmp_path: Path, maxima_exe: str):
    mxm = tmp_path / "frag.mxm"
    mxm.write_text(FRAGMENT_MXM)
    return load(str(mxm))


def test_python_fragment_keeps_names(fragment_spec) -> None:
    spec, poly = fragment_spec
    result = generate(spec, poly, LANGUAGES["python"], "fragment", "frag.py")
    assert [w.message for w in result.warnings] == [
        "parameter 'lambda' is written 'lambda_' in the Python fragment: 'lambda' is a Python "
        "keyword"]
    assert "p_" not in result.text and "c_" not in result.text
    scope = {("lambda_" if n == "lambda" else n): v for n, v in VALUES.items()}
    exec(compile(result.text, "frag.py", "exec"), scope)  # the user's code, names and all
    assert scope["a"] == WANT


@pytest.mark.parametrize("initialise,finalise", [
    ("initialise python { a = [0.0] * 3 }", "finalise python { total = sum(a) }"),
    ("initialise python {\n    a = [0.0] * 3\n    b = 1\n}",
     "finalise python {\n        total = sum(a)\n        if total:\n            b = 2\n}"),
    ("initialise python { a = [0.0] * 3\n    b = 1 }", "finalise python {\n\n  total = sum(a)\n\n}"),
])
def test_python_fragment_blocks_are_flush_left(tmp_path: Path, maxima_exe: str, initialise: str,
                                              finalise: str) -> None:
    """Python's top level has no indentation: blocks written on their brace's line or indented
    inside the braces (a reviewer's cases: IndentationError) come out flush left, nested lines
    keeping their relative indentation."""
    text = FRAGMENT_MXM.replace("initialise python {\na = [0.0] * 3\n}", initialise)
    text = text.replace("begin\n", finalise + "\nbegin\n")
    mxm = tmp_path / "frag.mxm"
    mxm.write_text(text)
    spec, poly = load(str(mxm))
    result = generate(spec, poly, LANGUAGES["python"], "fragment", "frag.py")
    scope = {("lambda_" if n == "lambda" else n): v for n, v in VALUES.items()}
    exec(compile(result.text, "frag.py", "exec"), scope)
    assert scope["a"] == WANT and scope["total"] == sum(WANT)


def test_c_and_rust_fragments_keep_names(fragment_spec, tmp_path: Path) -> None:
    spec, poly = fragment_spec
    gcc = require("gcc")
    c = generate(spec, poly, LANGUAGES["c"], "fragment", "frag.c")
    assert [w.message for w in c.warnings] == [
        "parameter 'int' is written 'int_' in the C fragment: 'int' is a C keyword"]
    (tmp_path / "frag.c").write_text(c.text + "\n")
    (tmp_path / "main.c").write_text(
        "#include <stdio.h>\nint main(void) {\n"
        + "".join(f"    double {'int_' if n == 'int' else n} = {v!r};\n" for n, v in VALUES.items())
        + '#include "frag.c"\n    printf("%a %a %a\\n", a[0], a[1], a[2]);\n    return 0;\n}\n')
    subprocess.run([gcc, "-std=c11", "-Wall", "-Werror", str(tmp_path / "main.c"), "-o",
                    str(tmp_path / "c")], check=True, cwd=tmp_path)
    out = subprocess.run([str(tmp_path / "c")], capture_output=True, text=True, check=True).stdout
    assert [float.fromhex(x) for x in out.split()] == WANT
    rust = generate(spec, poly, LANGUAGES["rust"], "fragment", "frag.rs")
    assert rust.warnings == ()  # `r#type` is how Rust writes the name type
    assert "r#type" in rust.text and "lambda" in rust.text and "p_" not in rust.text
    rustc = shutil.which("rustc") or str(Path.home() / ".cargo" / "bin" / "rustc")
    if not Path(rustc).exists():
        require("rustc")
    (tmp_path / "main.rs").write_text(
        "fn main() {\n"
        + "".join(f"    let {'r#type' if n == 'type' else n} = {v!r}_f64;\n"
                  for n, v in VALUES.items())
        + rust.text + '\n    println!("{:?}", a);\n}\n')
    subprocess.run([rustc, "-D", "warnings", "-A", "unused_mut", str(tmp_path / "main.rs"),
                    "-o", str(tmp_path / "r")], check=True, cwd=tmp_path)
    out = subprocess.run([str(tmp_path / "r")], capture_output=True, text=True, check=True).stdout
    assert [float(x) for x in out.strip("[]\n").split(",")] == WANT
