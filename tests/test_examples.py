"""The examples build and run in copies outside the checkout (a temporary folder holding only
examples/), print the right time, and rebuild only what depends on an edited .mxm (or on the .mac
file it loads). CMake finds max2code as a package (`max2code runtime --cmake-dir`), Cargo is
pointed at the runtime with the documented `cargo add`, Modula-2 builds with one `make`.

The scene (examples/README.md) closes a gap of 10 - 2t - t^2/4 to r1 + r2 = 1.5, so the first
contact is t = 2 (sqrt(12.5) - 2): computed here with mpmath, independently of Maxima and of
the runtimes.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

import mpmath
import pytest

from conftest import ROOT, require

EXPECTED = float(2 * (mpmath.sqrt(mpmath.mpf("12.5")) - 2))


@pytest.fixture
def tree(tmp_path: Path, maxima_exe: str) -> Path:
    """A copy of examples/ alone, away from the checkout: nothing of the repository's layout."""
    shutil.copytree(ROOT / "examples", tmp_path / "examples",
                    ignore=shutil.ignore_patterns("build", "target", "generated", "__pycache__",
                                                  "*.o"))
    assert not (tmp_path / "runtime").exists()
    return tmp_path / "examples"


@pytest.fixture
def env(tmp_path: Path) -> dict[str, str]:
    return {**os.environ, "PYTHONPATH": str(ROOT), "MAX2CODE_CACHE": str(tmp_path / "cache"),
            "MAX2CODE": f"{sys.executable} -m max2code"}


def run(args: list[str], cwd: Path, env: dict[str, str]) -> str:
    proc = subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, f"{args}:\n{proc.stdout}\n{proc.stderr}"
    return proc.stdout + proc.stderr


def collision_time(output: str) -> float:
    m = re.search(r"collision at t = (\S+)", output)
    assert m, output
    return float(m.group(1))


def check_time(output: str) -> None:
    assert collision_time(output) == pytest.approx(EXPECTED, rel=1e-13, abs=0)


def touch(path: Path) -> None:
    """Touch, a little after the last build: file times have a coarse (jiffy) granularity here."""
    time.sleep(0.05)
    os.utime(path)


def shift_lines(mxm: Path) -> None:
    """Change the .mxm so that the generated code changes (its #line numbers move)."""
    time.sleep(0.05)
    mxm.write_text("// one more line\n" + mxm.read_text())


def test_make(tree: Path, env: dict[str, str]) -> None:
    make = require("make")
    require("cc")
    folder = tree / "make"
    margs = [make, f"MAX2CODE={env['MAX2CODE']}"]
    check_time(run([*margs, "run"], folder, env))
    depfile = (folder / "build" / "circles.h.d").read_text()
    assert "../equations/circles.mxm" in depfile and "../equations/motion.mac" in depfile
    # the runtime's parts (roots/*.inc, included by max2code_roots.c) are its prerequisites
    parts = (folder / "build" / "max2code_roots.d").read_text()
    assert "roots/never_late.inc" in parts and "roots/prepare.inc" in parts, parts
    assert "Nothing to be done" in run([*margs, "all"], folder, env)
    for touched in ("circles.mxm", "motion.mac"):
        touch(tree / "equations" / touched)
        plan = run([*margs, "-n", "all"], folder, env)
        assert "--lang=c" in plan and "max2code_roots.c" not in plan, plan
        header = folder / "build" / "circles.h"
        before = header.stat().st_mtime_ns
        out = run([*margs, "all"], folder, env)
        assert "main.c" not in out and "max2code_roots" not in out, out  # same header: no rebuild
        assert header.stat().st_mtime_ns == before
    shift_lines(tree / "equations" / "circles.mxm")
    out = run([*margs, "run"], folder, env)
    assert "-c main.c" in out and "max2code_roots.c" not in out, out
    check_time(out)


def test_cmake(tree: Path, env: dict[str, str]) -> None:
    """find_package(max2code) through `max2code runtime --cmake-dir`: max2code_generate() and
    the max2code::runtime target, with nothing else of max2code's configured by hand."""
    cmake = require("cmake")
    require("ninja")
    folder = tree / "cmake"
    build = folder / "build"
    package = run([sys.executable, "-m", "max2code", "runtime", "--cmake-dir"], folder, env).strip()
    assert (Path(package) / "max2codeConfig.cmake").is_file()
    assert (Path(package) / "max2codeConfigVersion.cmake").is_file()
    out = run([cmake, "-S", str(folder), "-B", str(build), "-G", "Ninja",
               f"-Dmax2code_DIR={package}"], folder, env)
    assert "max2code" in (build / "CMakeCache.txt").read_text()
    out = run([cmake, "--build", str(build)], folder, env)
    assert "max2code circles.h" in out
    check_time(run([str(build / "collide")], folder, env))
    assert "no work to do" in run([cmake, "--build", str(build)], folder, env)
    for touched in ("circles.mxm", "motion.mac"):
        touch(tree / "equations" / touched)
        out = run([cmake, "--build", str(build)], folder, env)
        assert "max2code circles.h" in out and "Building C object" not in out, out
    shift_lines(tree / "equations" / "circles.mxm")
    out = run([cmake, "--build", str(build)], folder, env)
    assert "max2code circles.h" in out and "main.c.o" in out and "max2code_roots.c.o" not in out, out
    check_time(run([str(build / "collide")], folder, env))


def test_cmake_names_the_output_after_the_function(tree: Path, env: dict[str, str]) -> None:
    """max2code_generate() without OUTPUT names the file as `max2code build` does: after the
    declared function (main.c includes "circles.h"), not the file's stem ("two-circles.h")."""
    cmake = require("cmake")
    require("ninja")
    folder = tree / "cmake"
    (tree / "equations" / "circles.mxm").rename(tree / "equations" / "two-circles.mxm")
    lists = folder / "CMakeLists.txt"
    lists.write_text(lists.read_text().replace("equations/circles.mxm", "equations/two-circles.mxm"))
    package = run([sys.executable, "-m", "max2code", "runtime", "--cmake-dir"], folder, env).strip()
    build = folder / "build"
    run([cmake, "-S", str(folder), "-B", str(build), "-G", "Ninja", f"-Dmax2code_DIR={package}"],
        folder, env)
    out = run([cmake, "--build", str(build)], folder, env)
    assert "max2code circles.h" in out and not (build / "two-circles.h").exists(), out
    check_time(run([str(build / "collide")], folder, env))


def cargo_exe() -> str:
    home = Path.home() / ".cargo" / "bin" / "cargo"
    return shutil.which("cargo") or (str(home) if home.exists() else require("cargo"))


def test_cargo(tree: Path, env: dict[str, str]) -> None:
    cargo = cargo_exe()
    folder = tree / "cargo"
    env = {**env, "CARGO_TARGET_DIR": str(folder / "target")}
    # Copied out of the repository: point Cargo at the runtime once, as the README says.
    crate = run([sys.executable, "-m", "max2code", "runtime", "--lang", "rust", "--dir"], folder,
                env).strip()
    run([cargo, "add", "--offline", "max2code-runtime", "--path", crate], folder, env)
    check_time(run([cargo, "run", "--quiet", "--offline"], folder, env))
    out = run([cargo, "build", "-v", "--offline"], folder, env)
    assert "Fresh max2code-example" in out, out
    for touched in ("circles.mxm", "motion.mac"):
        touch(tree / "equations" / touched)
        out = run([cargo, "build", "-v", "--offline"], folder, env)
        assert "Dirty max2code-example" in out and f"{touched}` has changed" in out, out
        assert "Fresh max2code-runtime" in out, out
    check_time(run([cargo, "run", "--quiet", "--offline"], folder, env))


def test_m2(tree: Path, env: dict[str, str]) -> None:
    """One command: `make run` generates circles.mod/.def, compiles the C runtime and links."""
    make = require("make")
    require("gm2")
    folder = tree / "m2"
    margs = [make, f"MAX2CODE={env['MAX2CODE']}"]
    out = run([*margs, "run"], folder, env)
    assert collision_time(out) == pytest.approx(EXPECTED, rel=1e-15, abs=0)
    assert "Nothing to be done" in run([*margs, "all"], folder, env)
    shift_lines(tree / "equations" / "circles.mxm")
    out = run([*margs, "run"], folder, env)
    assert "--lang=m2" in out and "max2code_roots.c" not in out, out
    assert collision_time(out) == pytest.approx(EXPECTED, rel=1e-15, abs=0)


def test_python(tree: Path, env: dict[str, str]) -> None:
    folder = tree / "python"
    assert "regenerating" in run([sys.executable, "generate.py"], folder, env)
    check_time(run([sys.executable, "main.py"], folder, env))
    assert "up to date" in run([sys.executable, "generate.py"], folder, env)
    for touched in ("circles.mxm", "motion.mac"):
        touch(tree / "equations" / touched)
        assert "regenerating" in run([sys.executable, "generate.py"], folder, env)
        assert "up to date" in run([sys.executable, "generate.py"], folder, env)
    check_time(run([sys.executable, "main.py"], folder, env))


def test_the_python_example_reads_every_depfile_escape(tmp_path: Path) -> None:
    """examples/python/generate.py reads max2code's depfiles itself: a space, '#', '$' and ':'
    come escaped (README, dependency files); a folder with a ':' kept it regenerating on every
    run when '\\:' was not read back."""
    import importlib.util

    from max2code.maxima import depfile

    spec = importlib.util.spec_from_file_location("generate_example",
                                                  ROOT / "examples" / "python" / "generate.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    deps = ["/a b/c#d/e$f/g:h/x.mxm", "/a b/motion.mac"]
    d = tmp_path / "out.py.d"
    d.write_text(depfile.text(["out.py"], deps, phony=True))
    assert module.dependencies(d) == deps
