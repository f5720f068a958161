"""The rendering tests' libraries: installed by scripts/setup ('.[render,live]'), so a missing one
fails under CI (CI=true) and skips, with the install line, elsewhere."""

from __future__ import annotations

import importlib
import os
from types import ModuleType

import pytest


def need(module: str) -> ModuleType:
    try:
        return importlib.import_module(module)
    except ImportError:
        message = f"Python module '{module}' is not installed (run 'make setup')"
        if os.environ.get("CI"):
            pytest.fail(message + " -- required in CI")
        pytest.skip(message)
