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


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption("--update-golden", action="store_true",
                     help="rewrite tests/golden/ from the current output instead of comparing")


@pytest.fixture(scope="session")
def update_golden(request: pytest.FixtureRequest) -> bool:
    return bool(request.config.getoption("--update-golden"))


@pytest.fixture(scope="session")
def maxima_exe() -> str:
    return require("maxima")
