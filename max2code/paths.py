"""Where the templates, runtimes and shipped equations live.

In a checkout (or an editable install) they are the top-level folders beside the package; in an
installed wheel they travel inside it as `max2code/_data/` (see pyproject.toml). Either way a
build needs nothing but the installed package.
"""

from __future__ import annotations

import os
from pathlib import Path

PACKAGE = Path(__file__).resolve().parent
CHECKOUT = PACKAGE.parent
ROOT = CHECKOUT if (CHECKOUT / "templates").is_dir() else PACKAGE / "_data"


def templates_dir() -> Path:
    return ROOT / "templates"


def runtime_dir(lang: str) -> Path:
    return ROOT / "runtime" / lang


def display(path: Path) -> str:
    """A path as short as it can be: relative to the working folder when it lies below it, so
    diagnostics and `#line` directives read naturally."""
    rel = os.path.relpath(path)
    return str(path) if rel.startswith("..") else rel


def shipped_equations() -> list[str]:
    """The shipped equations/*.mxm, as `display` paths."""
    return [display(p) for p in sorted((ROOT / "equations").glob("*.mxm"))]
