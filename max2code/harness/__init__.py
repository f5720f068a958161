"""Build a generated module with a small driver program and run it on parameter vectors.

One module per language, each a `Harness` (base.py): it generates the module (module form,
default strategy, with variants), renders the driver from templates/<lang>/harness.j2, builds
both with the language's own tools and runs them. `max2code check` (check.py) knows no language
rule: adding a language means adding one harness module and one line here.
"""

from __future__ import annotations

from .base import Case, Harness, HarnessError, Outcome, Unit
from .c import CHarness
from .m2 import M2Harness
from .python import PythonHarness
from .rust import RustHarness

HARNESSES: dict[str, Harness] = {
    "c": CHarness(),
    "python": PythonHarness(),
    "m2": M2Harness(),
    "rust": RustHarness(),
}

__all__ = ["Case", "Harness", "HarnessError", "Outcome", "Unit", "HARNESSES"]
