"""Issue 12's generated-name clashes that exit 0: a parameter named like a name the generated
code (or its runtime) defines. Either max2code refuses the equation with a diagnostic, or what
it writes compiles. The general scheme (no generated identifier can clash with a user's name,
in any language) is issue 11 item 1 (max2code/codegen/names.py); tests/test_names.py checks it on a
corpus of every language's keywords and predeclared names, these are the issue's reproducers.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT, require

# (language, parameter name); the equation's function is `clash`.
CASES = [("c", "clash_DEGREE"), ("c", "clash_NPARAMS"), ("c", "M2C_MAX_DEGREE"),
         ("rust", "None"), ("rust", "Some"), ("rust", "Ok"), ("rust", "Err")]


@pytest.fixture(scope="module")
def rlib(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("rlib") / "libmax2code_runtime.rlib"
    subprocess.run([require("rustc"), "--edition", "2021", "--crate-type=lib", "--crate-name",
                    "max2code_runtime", str(ROOT / "runtime/rust/src/lib.rs"), "-o", str(out)],
                   check=True, capture_output=True)
    return out


@pytest.mark.parametrize("lang,name", CASES, ids=[f"{lang}-{name}" for lang, name in CASES])
def test_a_parameter_named_like_a_generated_name(lang: str, name: str, tmp_path: Path,
                                                 rlib: Path, maxima_exe: str) -> None:
    mxm = tmp_path / "clash.mxm"
    mxm.write_text(f"function clash\nparameters {name}, b\nbegin\n(t - {name})*(t - b);\nend\n")
    out = tmp_path / ("clash.h" if lang == "c" else "clash.rs")
    proc = subprocess.run([sys.executable, "-m", "max2code", f"--lang={lang}", str(mxm), "-o",
                           str(out)], cwd=ROOT, capture_output=True, text=True, timeout=300,
                          env={**os.environ, "MAX2CODE_CACHE": str(tmp_path / "cache")})
    if proc.returncode == 1:  # refused: then with a diagnostic at the .mxm
        assert proc.stderr.startswith(f"{mxm}:"), proc.stderr
        return
    assert proc.returncode == 0, proc.stderr
    if lang == "c":
        compiled = subprocess.run([require("gcc"), "-std=c11", "-Wall", "-Wextra", "-Werror",
                                   "-fsyntax-only", f"-I{ROOT / 'runtime/c'}", "-x", "c", str(out)],
                                  capture_output=True, text=True)
    else:
        compiled = subprocess.run([require("rustc"), "--edition", "2021", "--crate-type=lib",
                                   "--emit=metadata", "--crate-name", "clash", "--extern",
                                   f"max2code_runtime={rlib}", "-A", "dead_code", str(out), "-o",
                                   str(tmp_path / "clash.rmeta")], capture_output=True, text=True)
    assert compiled.returncode == 0, compiled.stderr[-1500:]
