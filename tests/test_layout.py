"""The package's layering rules (docs/layout.md): no module imports another's private names,
and nothing but the entry point imports cli.py (the subcommands once imported their options
back from it inside functions, a hidden cycle)."""

from __future__ import annotations

import ast
from pathlib import Path

from conftest import ROOT

PACKAGE = ROOT / "max2code"


def imports(path: Path) -> list[ast.ImportFrom]:
    return [n for n in ast.walk(ast.parse(path.read_text(encoding="utf-8"))) if isinstance(n, ast.ImportFrom)]


def test_no_private_names_cross_modules() -> None:
    found = [f"{path.relative_to(ROOT)}:{node.lineno}: {alias.name}"
             for path in sorted(PACKAGE.rglob("*.py")) for node in imports(path)
             for alias in node.names
             if alias.name.startswith("_") and not alias.name.startswith("__")
             and (node.level > 0 or (node.module or "").startswith("max2code"))]
    assert found == []


def test_only_the_entry_point_imports_cli() -> None:
    found = [f"{path.relative_to(ROOT)}:{node.lineno}"
             for path in sorted(PACKAGE.rglob("*.py")) if path.name != "__main__.py"
             for node in imports(path)
             if (node.level == 1 and path.parent == PACKAGE and node.module == "cli")
             or (node.level >= 1 and node.module is None and any(a.name == "cli" for a in node.names))
             or node.module == "max2code.cli"
             or (node.level == 2 and node.module == "cli")]
    assert found == []
