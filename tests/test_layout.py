"""The package's layering rules (docs/layout.md): the modules are grouped by stage (maxima/,
front/, codegen/, commands/) beside the feature packages, with only small shared utilities
left flat; a stage imports only stages below it; nothing but the entry point imports cli.py
(the subcommands once imported their options back from it inside functions, a hidden cycle);
no module imports another's private names."""

from __future__ import annotations

import ast
from pathlib import Path

from conftest import ROOT

PACKAGE = ROOT / "max2code"
# The modules left at the top: the entry point and utilities every stage may use.
FLAT = {"__init__", "__main__", "cli", "cache", "diagnostics", "jsonsafe", "machine", "mdtext",
        "output", "paths"}
# Stage packages, lowest first: a module may import its own stage and the ones before it.
STAGES = {"maxima": 0, "front": 0, "codegen": 1, "commands": 2}


def imports(path: Path) -> list[ast.ImportFrom]:
    return [n for n in ast.walk(ast.parse(path.read_text(encoding="utf-8"))) if isinstance(n, ast.ImportFrom)]


def module_of(path: Path) -> str:
    parts = path.relative_to(ROOT).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def imported(path: Path) -> list[tuple[int, str]]:
    """(line, absolute module) for every module `path` imports from max2code, at the top or
    inside a function: `from .a import b` names .a, and .a.b too when b is a module."""
    here = module_of(path).split(".")
    package = here if path.name == "__init__.py" else here[:-1]
    found = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found += [(node.lineno, a.name) for a in node.names if a.name.startswith("max2code")]
        elif isinstance(node, ast.ImportFrom):
            base = (".".join(package[:len(package) - node.level + 1] + ([node.module] if node.module else []))
                    if node.level else node.module or "")
            if not base.startswith("max2code"):
                continue
            found.append((node.lineno, base))
            for a in node.names:
                sub = ROOT / (base + "." + a.name).replace(".", "/")
                if sub.with_suffix(".py").exists() or sub.is_dir():
                    found.append((node.lineno, f"{base}.{a.name}"))
    return found


def stage_of(module: str) -> str | None:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 and parts[1] in STAGES else None


def test_no_private_names_cross_modules() -> None:
    found = [f"{path.relative_to(ROOT)}:{node.lineno}: {alias.name}"
             for path in sorted(PACKAGE.rglob("*.py")) for node in imports(path)
             for alias in node.names
             if alias.name.startswith("_") and not alias.name.startswith("__")
             and (node.level > 0 or (node.module or "").startswith("max2code"))]
    assert found == []


def test_only_the_entry_point_imports_cli() -> None:
    found = [f"{path.relative_to(ROOT)}:{line}"
             for path in sorted(PACKAGE.rglob("*.py")) if path != PACKAGE / "__main__.py"
             for line, module in imported(path) if module == "max2code.cli"]
    assert found == []


def test_the_resolver_sees_every_kind_of_import(tmp_path: Path) -> None:
    """The rules below are only as good as imported(): relative at any depth, `from . import
    module`, absolute, and inside a function."""
    path = PACKAGE / "codegen" / "poly.py"
    modules = {m for _, m in imported(path)}
    assert {"max2code.maxima.session", "max2code.diagnostics", "max2code.codegen.expr"} <= modules
    modules = {m for _, m in imported(PACKAGE / "commands" / "sim.py")}
    assert "max2code.engine.scenefile" in modules  # imported inside a function


def test_only_shared_utilities_stay_flat() -> None:
    flat = {p.stem for p in PACKAGE.glob("*.py")}
    assert flat == FLAT, "a new module belongs in a stage package (docs/layout.md), or in FLAT"
    assert all((PACKAGE / stage / "__init__.py").is_file() for stage in STAGES)


def test_stages_import_only_downwards() -> None:
    """maxima/ and front/ know nothing of code generation, codegen/ nothing of the commands;
    the flat utilities import no stage at all."""
    found = []
    for path in sorted(PACKAGE.rglob("*.py")):
        here = module_of(path)
        mine = stage_of(here)
        flat_utility = here.count(".") == 1 and here.split(".")[1] in FLAT - {"cli", "__main__"}
        for line, module in imported(path):
            theirs = stage_of(module)
            if theirs is None or theirs == mine:
                continue
            if (flat_utility or (mine is not None and STAGES[theirs] > STAGES[mine])
                    or (theirs == "commands" and here != "max2code.cli")):
                found.append(f"{path.relative_to(ROOT)}:{line}: {module}")
    assert found == []
