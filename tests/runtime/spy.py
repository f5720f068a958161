"""Replacing a function of the pure-Python solver for a test (a spy, a counter), wherever the
solver calls it.  The solver is a package of parts (max2code_runtime/solver/), and a part calls
another part's function through its own import of it: so the function is replaced in the part
that defines it, in every part that imports it and in the package itself (its facade)."""

from __future__ import annotations

import sys
from typing import Any

import pytest


def patch_solver(monkeypatch: pytest.MonkeyPatch, name: str, value: Any) -> None:
    """monkeypatch.setattr(solver, name, value) for every module of the solver that holds the
    function the package holds now (all of them, once patched: patches nest)."""
    from max2code_runtime import solver

    old = getattr(solver, name)
    prefix = solver.__name__
    modules = [m for key, m in list(sys.modules.items())
               if key == prefix or key.startswith(prefix + ".")]
    held = [m for m in modules if getattr(m, name, None) is old]
    assert solver in held and len(held) >= 2, f"{name}: not a function of a solver part"
    for module in held:
        monkeypatch.setattr(module, name, value)
