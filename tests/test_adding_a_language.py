"""docs/adding-a-language.md, followed to the letter in a copy of the checkout: three folders
and one registry line make a language that every command knows. A rule about languages kept
anywhere else (an if-chain on a language's name, a second list) breaks one of these steps."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT

PRINTER = '''"""Toy: Python under another name, enough to show that the registry is the only list."""

from dataclasses import dataclass

from ..python.printer import Python


@dataclass(frozen=True)
class Toy(Python):
    name: str = "toy"
    title: str = "Toy"
'''

HARNESS = '''from ..python.harness import PythonHarness


class ToyHarness(PythonHarness):
    lang = "toy"
'''

RUNTIME = '''from ...paths import runtime_dir


def info() -> dict[str, str]:
    return {"dir": str(runtime_dir("toy")), "cflags": "", "sources": "", "libs": "",
            "toyflags": "--toy"}
'''

ENTRY = '''from ..entry import Entry
from .printer import Toy
from .runtime import info

ENTRY = Entry(Toy(), __name__, harness="ToyHarness", runtime=info)
'''


@pytest.fixture
def copy(tmp_path: Path) -> Path:
    """The package, templates, runtimes and equations: what a contributor's checkout holds."""
    ignore = shutil.ignore_patterns("__pycache__", "target", "*.so", "*.o")
    for folder in ("max2code", "templates", "runtime", "equations", "tests"):
        shutil.copytree(ROOT / folder, tmp_path / folder, ignore=ignore)
    return tmp_path


def follow_the_recipe(root: Path) -> None:
    folder = root / "max2code" / "languages" / "toy"
    folder.mkdir()
    for name, text in (("printer.py", PRINTER), ("harness.py", HARNESS),
                       ("runtime.py", RUNTIME), ("__init__.py", ENTRY)):
        (folder / name).write_text(text)
    shutil.copytree(root / "templates" / "python", root / "templates" / "toy")
    shutil.copytree(root / "runtime" / "python", root / "runtime" / "toy")
    registry = root / "max2code" / "languages" / "__init__.py"
    text = registry.read_text()
    assert text.count('    "rust": rust.ENTRY,\n') == 1  # the registry line the docs name
    text = text.replace('    "rust": rust.ENTRY,\n', '    "rust": rust.ENTRY,\n    "toy": toy.ENTRY,\n')
    text = text.replace("from . import c, m2, python, rust\n", "from . import c, m2, python, rust, toy\n")
    registry.write_text(text)


def run(root: Path, *args: str) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "PYTHONPATH": str(root), "MAX2CODE_CACHE": str(root / "cache")}
    return subprocess.run([sys.executable, "-m", "max2code", *args], cwd=root, env=env,
                          capture_output=True, text=True, timeout=900)


def test_a_new_language_is_three_folders_and_one_line(copy: Path, maxima_exe: str) -> None:
    before = run(copy, "--lang=toy", "equations/point-line.mxm")
    assert before.returncode == 2 and "invalid choice: 'toy'" in before.stderr
    follow_the_recipe(copy)
    out = copy / "point_line.py"
    generated = run(copy, "--lang=toy", "equations/point-line.mxm", "-o", str(out))
    assert generated.returncode == 0, generated.stderr
    python = run(copy, "--lang=python", "equations/point-line.mxm")
    assert python.returncode == 0 and out.read_text() == python.stdout  # Python by another name
    assert run(copy, "runtime", "--lang", "toy", "--dir").stdout.strip() == str(copy / "runtime" / "toy")
    assert run(copy, "runtime", "--lang", "toy").stdout.count("toyflags: --toy") == 1
    built = run(copy, "build", "-o", "out", "--lang", "toy", "equations/point-line.mxm")
    assert built.returncode == 0 and (copy / "out" / "toy" / "point_line.py").is_file(), built.stderr
    checked = run(copy, "check", "--lang", "toy", "equations/point-line.mxm")
    assert checked.returncode == 0, checked.stdout + checked.stderr
    assert "toy" in checked.stdout
