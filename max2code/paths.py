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


def inputs_or_folder(inputs: list[str]) -> list[str]:
    """The files named on the command line, else the .mxm files of the current folder (sorted),
    as Make uses the Makefile it finds: a command run in a user's folder works on the user's
    equations, never on the shipped ones. Empty when there are none (a usage error)."""
    if inputs:
        return inputs
    return sorted(str(p) for p in Path(".").glob("*.mxm") if p.is_file())


def no_inputs(command: str) -> str:
    """The usage error for a command given no .mxm and finding none in the current folder."""
    return (f"no FILE.mxm given, and the current folder ({os.path.abspath('.')}) has no .mxm "
            f"file; name the equations: max2code {command} FILE.mxm ...")
