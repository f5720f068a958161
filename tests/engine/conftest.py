"""The engine's tests: the C core is built once per session (into max2code's cache)."""

from __future__ import annotations

import importlib.util
import os

import pytest

from conftest import require


@pytest.fixture(scope="session")
def engine():
    """max2code.engine with its library built (make, a C compiler, Maxima and cffi needed)."""
    for tool in ("make", "cc", "maxima"):
        require(tool)
    if importlib.util.find_spec("cffi") is None:
        message = "cffi is not installed (run 'make setup')"
        if os.environ.get("CI"):
            pytest.fail(message + " -- required in CI")
        pytest.skip(message)
    import max2code.engine as eng
    from max2code.engine.binding import load
    load()
    return eng
