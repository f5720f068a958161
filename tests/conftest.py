"""Shared test plumbing: tools that must exist in CI, and the repository's folders."""

from __future__ import annotations

import os
import shutil
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests"))
sys.path.insert(0, str(ROOT / "runtime" / "python"))


def require(tool: str) -> str:
    """The tool's path; a missing tool fails under CI (CI=true) and skips, clearly, elsewhere."""
    path = shutil.which(tool)
    if path is None:
        message = f"'{tool}' is not installed (run 'make setup')"
        if os.environ.get("CI"):
            pytest.fail(message + " -- required in CI")
        pytest.skip(message)
    return path


def require_module(name: str):
    """An installed Python module (scripts/setup installs the extras the tests need); a missing
    one fails under CI (CI=true) and skips, clearly, elsewhere."""
    import importlib
    try:
        return importlib.import_module(name)
    except ImportError:
        message = f"Python module '{name}' is not installed (run 'make setup')"
        if os.environ.get("CI"):
            pytest.fail(message + " -- required in CI")
        pytest.skip(message)


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption("--update-golden", action="store_true",
                     help="rewrite tests/golden/ from the current output instead of comparing")


@pytest.fixture(scope="session")
def update_golden(request: pytest.FixtureRequest) -> bool:
    return bool(request.config.getoption("--update-golden"))


@pytest.fixture(scope="session")
def maxima_exe() -> str:
    return require("maxima")


def corrected_paper_point_line(folder: Path) -> tuple[Path, list[int]]:
    """equations/paper/point-line.mxm with the declared term count fixed (5 coefficients, not
    4) and the coefficient array renamed from `a`, which is also a parameter of the equation;
    and the lines of its 5 `term` blocks."""
    text = (ROOT / "equations" / "paper" / "point-line.mxm").read_text()
    text = text.replace("polynomial terms 4", "polynomial terms 5")
    text = text.replace("a: ARRAY [0..3] OF REAL", "coef: ARRAY [0..4] OF REAL")
    text = text.replace("term 3 { a[3] := }", "term 3 { a[3] := }\nterm 4 { a[4] := }")
    for k in range(5):
        text = text.replace(f"{{ a[{k}] := }}", f"{{ coef[{k}] := }}")
    text = text.replace("findSmallestPositiveRoot(a)", "findSmallestPositiveRoot(coef)")
    assert text.count("coef[") == 5
    out = folder / "point-line.mxm"
    out.write_text(text)
    lines = text.splitlines()
    return out, [1 + next(i for i, ln in enumerate(lines) if ln.startswith(f"term {k} "))
                 for k in range(5)]
