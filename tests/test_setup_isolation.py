"""Two clones on one machine never touch each other (issue 37, item 4).

scripts/setup installs the Python package editable into the checkout's own virtual environment
(.venv), never into the system's Python: a second clone's setup must not re-point `max2code`,
or any test's `python -m max2code` subprocess, at the other checkout. The test makes a second
clone, runs its setup (the README's commands run the same script), and asks each environment
which code it imports, from a neutral folder so that the current directory cannot decide.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

from conftest import ROOT, require

WHERE = "import max2code, max2code_runtime, os; print(os.path.realpath(max2code.__file__)); " \
        "print(os.path.realpath(max2code_runtime.__file__))"


def _imports(python: Path | str, cwd: Path) -> list[Path]:
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}
    out = subprocess.run([str(python), "-c", WHERE], cwd=cwd, env=env, capture_output=True,
                         text=True, timeout=120, check=True).stdout.split()
    return [Path(p) for p in out]


def test_this_run_uses_this_checkout(tmp_path: Path) -> None:
    """The interpreter running the tests (and so every sys.executable subprocess) imports this
    checkout's max2code and runtime, even from a folder outside it."""
    here = ROOT.resolve()
    for path in _imports(sys.executable, tmp_path):
        assert path.is_relative_to(here), f"{path} is not in the checkout under test {here}"


def test_a_second_clone_gets_its_own_environment(tmp_path: Path) -> None:
    require("git")
    if not (ROOT / ".git").exists():
        import pytest
        pytest.skip("not a git checkout")
    other = tmp_path / "other-clone"
    subprocess.run(["git", "clone", "-q", "--no-hardlinks", str(ROOT), str(other)], check=True,
                   timeout=300)
    env = {k: v for k, v in os.environ.items()
           if k not in ("PYTHONPATH", "PYTHONHOME", "VIRTUAL_ENV")}
    # The clone's setup, as `make` / `make test` run it; Debian packages are already here.
    proc = subprocess.run([str(other / "scripts" / "setup")], cwd=other, env=env,
                          capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    theirs = other / ".venv" / "bin" / "python"
    assert theirs.exists()
    for path in _imports(theirs, tmp_path):
        assert path.is_relative_to(other.resolve()), path
    # ... and ours still imports ours, after the other clone's setup ran.
    for path in _imports(sys.executable, tmp_path):
        assert path.is_relative_to(ROOT.resolve()), path
    # The system's Python was not given either clone (setup installs into .venv only).
    system = shutil.which("python3", path=os.pathsep.join(
        p for p in os.environ.get("PATH", "").split(os.pathsep)
        if not Path(p).resolve().is_relative_to(ROOT.resolve())
        and not Path(p).resolve().is_relative_to(other.resolve())))
    if system:
        probe = subprocess.run([system, "-c", "import max2code, os; "
                                "print(os.path.realpath(max2code.__file__))"],
                               cwd=tmp_path, env=env, capture_output=True, text=True, timeout=60)
        assert str(other.resolve()) not in probe.stdout
