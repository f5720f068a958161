"""Hostile paths never become code: folder and file names drawn from the characters that end
comments, strings, lines and Make rules are run through max2code in every language, and each
output must still compile (gcc -fsyntax-only and an object with no global symbol, ast.parse,
rustc --emit=metadata, gm2 -c) and, with its comments and line directives removed, equal the
output of the same equation at a plain path: nothing a path spells reaches the code itself.
Depfiles are read back by GNU Make and by Ninja, which must see exactly the real paths; a path
they cannot express is refused with a diagnostic, before any output is written.

Scale: MAX2CODE_FUZZ_PATH_EXAMPLES (default 12; each example compiles four outputs).
"""

from __future__ import annotations

import ast
import contextlib
import io
import os
import re
import shutil
import subprocess
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from conftest import ROOT, require

from max2code import cli

EXAMPLES = int(os.environ.get("MAX2CODE_FUZZ_PATH_EXAMPLES", "12"))
EQUATION = ROOT / "equations" / "point-line.mxm"  # declares `function point_line`

# Pieces of hostile names: comment and string delimiters of all four languages, Make's and the
# shell's specials, line ends, escapes, bidi controls, a byte that is not UTF-8 (surrogateescape),
# and whole injections.
PIECES = ["*/", "/*", "(*", "*)", "//", '"', "'", "\\", "\n", "\r", "\t", "$", "$$", "#", ":",
          " ", ";", "=", "?", "??/", "{", "}", "%", "\u202e", "\u2028", "\x1b", "\x0c", "é",
          "\xa0", "\U0001f600", "\udcff", "~", "-", "|", "&", "`", "<", ">", "(", ")", "[", "]",
          "*", "a", "x1", "\\N", '"""', "int injected(void) { return 42; }", "\n#include <x>\n",
          "\nCC=touch pwned;true\nx:", "}\npub fn injected() {}\n", "\nimport os\n",
          "END point_line.\n", "${IFS}"]


def hostile_name() -> st.SearchStrategy[str]:
    return st.lists(st.sampled_from(PIECES), min_size=1, max_size=5).map("".join).filter(
        lambda s: "/" not in s.replace("//", "").replace("*/", "").replace("/*", "")
        and s not in (".", ".."))


def component(name: str) -> str:
    """A path component: '/' (which some pieces hold) cannot be in a file name."""
    return name.replace("/", "\u2215")


@pytest.fixture(scope="module")
def rust_runtime(tmp_path_factory: pytest.TempPathFactory) -> Path:
    rustc = require("rustc")
    out = tmp_path_factory.mktemp("rlib") / "libmax2code_runtime.rlib"
    subprocess.run([rustc, "--edition", "2021", "--crate-type=lib", "--crate-name",
                    "max2code_runtime", "-O", str(ROOT / "runtime/rust/src/lib.rs"), "-o", str(out)],
                   check=True, capture_output=True)
    return out


class Plain(dict):  # type: ignore[type-arg]
    def __repr__(self) -> str:  # hypothesis prints the arguments of a failing example
        return "<plain outputs>"


@pytest.fixture(scope="module")
def plain(tmp_path_factory: pytest.TempPathFactory, maxima_exe: str) -> dict[str, str]:
    """Each language's output at a plain path, with comments and directives removed."""
    folder = tmp_path_factory.mktemp("plain")
    shutil.copy(EQUATION, folder / "eq.mxm")
    (folder / "out").mkdir()
    out = Plain()
    with _cwd(folder):
        for lang, ext in LANGS.items():
            rc, err = _run(["--lang", lang, "--emit=module", "eq.mxm", "-o", f"out/point_line{ext}"])
            assert rc == 0, err
            out[lang] = strip(lang, (folder / "out" / f"point_line{ext}").read_text())
    return out


LANGS = {"c": ".h", "python": ".py", "rust": ".rs", "m2": ".mod"}


@pytest.fixture(scope="module", autouse=True)
def private_cache(tmp_path_factory: pytest.TempPathFactory):  # type: ignore[no-untyped-def]
    """In-process runs use a cache of their own (one Maxima run serves every path)."""
    old = os.environ.get("MAX2CODE_CACHE")
    os.environ["MAX2CODE_CACHE"] = str(tmp_path_factory.mktemp("cache"))
    yield
    if old is None:
        del os.environ["MAX2CODE_CACHE"]
    else:
        os.environ["MAX2CODE_CACHE"] = old


@contextlib.contextmanager
def _cwd(path: Path):  # type: ignore[no-untyped-def]
    old = os.getcwd()
    os.chdir(path)
    try:
        yield
    finally:
        os.chdir(old)


def _run(argv: list[str]) -> tuple[int, str]:
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        rc = cli.main(argv)
    return rc, err.getvalue()


def strip(lang: str, text: str) -> str:
    """The code without its comments and line directives (each language's own lexing rules)."""
    if lang in ("c", "m2"):
        text = re.sub(r"^#line .*$", "", text, flags=re.M)
    if lang == "c":
        text = re.sub(r"/\*[\s\S]*?\*/", "", text)
    elif lang == "m2":
        text = _strip_nested(text, "(*", "*)")
    elif lang == "rust":
        text = re.sub(r"//[^\n]*", "", text)
    elif lang == "python":
        text = re.sub(r'^"""[\s\S]*?"""$', "", text, count=1, flags=re.M)  # the module docstring
        text = re.sub(r"#[^\n]*", "", text)
    return "\n".join(line.rstrip() for line in text.splitlines() if line.strip())


def _strip_nested(text: str, open_: str, close: str) -> str:
    out, depth, i = [], 0, 0
    while i < len(text):
        if text.startswith(open_, i):
            depth, i = depth + 1, i + 2
        elif depth and text.startswith(close, i):
            depth, i = depth - 1, i + 2
        else:
            if not depth:
                out.append(text[i])
            i += 1
    return "".join(out)


def compiles(lang: str, path: Path, rlib: Path) -> None:
    path = Path(os.path.abspath(path))  # a name starting with '-' is no option
    folder = path.parent
    if lang == "c":
        gcc = require("gcc")
        flags = ["-std=c11", "-Wall", "-Wextra", "-Werror", "-pedantic", f"-I{ROOT / 'runtime/c'}"]
        _check([gcc, *flags, "-fsyntax-only", "-x", "c", str(path)])
        obj = folder / "unit.o"
        subprocess.run([gcc, f"-I{ROOT / 'runtime/c'}", "-c", "-x", "c", str(path), "-o", str(obj)],
                       check=True, capture_output=True)
        symbols = subprocess.run(["nm", "-g", "--defined-only", str(obj)], check=True,
                                 capture_output=True, text=True).stdout
        assert symbols == "", f"a header of static inline functions defines {symbols!r}"
    elif lang == "python":
        tree = ast.parse(path.read_text(encoding="utf-8"))
        names = {t.id for node in tree.body if isinstance(node, ast.Assign) for t in node.targets
                 if isinstance(t, ast.Name)}
        names |= {node.name for node in tree.body if isinstance(node, ast.FunctionDef)}
        assert "injected" not in names
    elif lang == "rust":  # rustc wants a UTF-8 input path: the text is what is checked
        with tempfile.TemporaryDirectory() as plain_dir:
            shutil.copy(path, os.path.join(plain_dir, "m.rs"))
            _check([require("rustc"), "--edition", "2021", "--crate-type=lib", "--emit=metadata",
                    "--crate-name", "m", "--extern", f"max2code_runtime={rlib}", "-D", "warnings",
                    "-A", "dead_code", "m.rs"], plain_dir)
    elif lang == "m2":
        _check([require("gm2"), "-fiso", "-fcpp", "-Wall", "-Werror", f"-I{ROOT / 'runtime/m2'}",
                "-c", path.name, "-o", "m.o"], str(folder))


def _check(argv: list[str], cwd: str | None = None) -> None:
    proc = subprocess.run(argv, cwd=cwd, capture_output=True, text=True, errors="replace")
    assert proc.returncode == 0, proc.stderr[-2000:]


def make_sees(dep: Path, target: str, source: str) -> None:
    """GNU Make reads the depfile's rule as `target: source`: up to date while the target is
    newer, out of date once the source is; never an error (exit 2), never another file."""
    shutil.copy(dep, "copy.d")
    Path("Makefile").write_text("include copy.d\n%::\n\t@:\n")  # a recipe for every target
    os.utime(os.fsencode(source), (1_000_000, 1_000_000))
    os.utime(os.fsencode(target), (2_000_000, 2_000_000))
    make = [require("make"), "-q", "-f", "Makefile"]  # the depfile's rule is the default goal
    assert subprocess.run(make, capture_output=True).returncode == 0
    os.utime(os.fsencode(source), (3_000_000, 3_000_000))
    assert subprocess.run(make, capture_output=True).returncode == 1
    os.remove("Makefile")


def ninja_sees(dep: Path, target: str, expected: list[str]) -> None:
    folder = Path("ninja")
    folder.mkdir()
    shutil.copy(dep, folder / "copy.d")
    (folder / "build.ninja").write_text(
        "rule gen\n  command = cp copy.d gen.d\n  depfile = gen.d\n  deps = gcc\n"
        "build ninja-out: gen\n")
    subprocess.run([require("ninja"), "-C", str(folder)], check=True, capture_output=True)
    listed = subprocess.run([require("ninja"), "-C", str(folder), "-t", "deps", "ninja-out"],
                            check=True, capture_output=True, text=True).stdout.split("\n")[1:]
    # Ninja keeps the paths as written, in canonical form (no './'), each behind four spaces.
    # Only those four go: a path may begin or end with its own blanks (a folder named ' ').
    listed = [line[4:] for line in listed if line.startswith("    ")]
    assert listed == [os.path.normpath(p) for p in expected]
    shutil.rmtree(folder)


@settings(max_examples=EXAMPLES, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(folder=hostile_name(), stem=hostile_name(), out_folder=hostile_name())
@example(folder=" ", stem="\\", out_folder="-")  # CI, 2026-12-03: the folder's own space
def test_hostile_paths_never_become_code(folder: str, stem: str, out_folder: str,
                                         plain: dict[str, str], rust_runtime: Path,
                                         tmp_path: Path) -> None:
    with tempfile.TemporaryDirectory(dir=tmp_path) as tmp, _cwd(Path(tmp)):
        src_dir, out_dir = "./" + component(folder), "./" + component(out_folder)
        os.makedirs(os.fsencode(src_dir), exist_ok=True)
        source = os.path.join(src_dir, component(stem) + ".mxm")
        shutil.copy(EQUATION, os.fsencode(source))
        for lang, ext in LANGS.items():
            output = os.path.join(out_dir, f"point_line{ext}")
            os.makedirs(os.fsencode(out_dir), exist_ok=True)
            rc, err = _run(["--lang", lang, "--emit=module", source, "-o", output, "-MD", "-MP"])
            if rc != 0:  # only a depfile that cannot express a path may fail, and nothing is written
                assert "cannot be written in a dependency file" in err, err
                assert not os.path.exists(os.fsencode(output))
                rc, err = _run(["--lang", lang, "--emit=module", source, "-o", output])
                assert rc == 0, err
            else:
                dep = Path(os.fsdecode(os.fsencode(output + ".d")))
                if lang == "c":
                    make_sees(dep, output, source)
                    ninja_sees(dep, output, [source])
            out_path = Path(output)
            text = out_path.read_text(encoding="utf-8")
            assert strip(lang, text) == plain[lang], lang
            compiles(lang, out_path, rust_runtime)
        assert not list(Path(".").rglob("pwned"))


def test_the_issue_reproducers(tmp_path: Path, maxima_exe: str) -> None:
    """Issue 12's two paths: a folder that closed the C header's comment and defined a
    function, and one whose newline ended the depfile's rule and set CC."""
    with _cwd(tmp_path):
        inject = "x*/ int injected_by_path(void) { return 42; } /*"
        os.makedirs(inject)
        shutil.copy(EQUATION, os.path.join(inject, "eq.mxm"))
        assert _run(["--lang=c", os.path.join(inject, "eq.mxm"), "-o", "eq.h"])[0] == 0
        main = tmp_path / "main.c"
        main.write_text('#include "eq.h"\nint main(void) { return injected_by_path(); }\n')
        proc = subprocess.run([require("gcc"), "-std=c11", "-Werror", f"-I{ROOT / 'runtime/c'}", "-c", str(main)],
                              capture_output=True, text=True, cwd=tmp_path)
        assert proc.returncode != 0 and "injected_by_path" in proc.stderr  # undeclared now

        newline = ".\nCC=touch${IFS}pwned;true\nx:"
        os.makedirs(newline)
        shutil.copy(EQUATION, os.path.join(newline, "eq.mxm"))
        rc, err = _run(["--lang=python", os.path.join(newline, "eq.mxm"), "-o", "eq.py", "-MD"])
        assert rc == 1
        assert err.splitlines()[0] == (
            ".\\nCC=touch${IFS}pwned;true\\nx:/eq.mxm:1:1: error: this path cannot be written in "
            "a dependency file: Make and Ninja have no escape for '\\n' (rename it, or do without "
            "-MD/-MF)")
        assert not (tmp_path / "eq.py").exists() and not (tmp_path / "eq.py.d").exists()
        assert _run(["--lang=python", os.path.join(newline, "eq.mxm"), "-o", "eq.py"])[0] == 0
        ast.parse((tmp_path / "eq.py").read_text())
