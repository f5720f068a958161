"""The command line as a Unix user meets it: a closed pipe, the help, a command run in the
user's own folder with no file named."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT

from max2code.cli import SUBCOMMANDS, SUMMARIES

ENV = {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), str(ROOT / "runtime" / "python")])}


def closed_reader(args: list[str], cwd: Path = ROOT) -> tuple[int, str]:
    """Run max2code with its standard output a pipe whose reader has already gone (as after
    `| head -3`): (exit status, standard error)."""
    read, write = os.pipe()
    os.close(read)
    proc = subprocess.run([sys.executable, "-m", "max2code", *args], stdout=write,
                          stderr=subprocess.PIPE, text=True, cwd=cwd, env=ENV, timeout=600)
    os.close(write)
    return proc.returncode, proc.stderr


@pytest.mark.parametrize("args", [
    ["runtime"],
    ["scene", "examples/frozen/billiards-break.json"],
    ["--lang=c", "equations/point-line.mxm"],
    ["vectors", "equations/point-line.mxm"],
], ids=lambda a: " ".join(a)[:30])
def test_a_closed_pipe_ends_quietly(args: list[str], maxima_exe: str) -> None:
    status, stderr = closed_reader(args)
    assert status == 141, stderr  # 128 + SIGPIPE, as a Unix tool killed by it
    assert stderr == ""


@pytest.mark.parametrize("args", [["--help"], ["check", "--help"]])
def test_help_into_a_closed_pipe_is_quiet(args: list[str]) -> None:
    """argparse itself ignores a failed write of the help and exits 0; either way, no noise."""
    status, stderr = closed_reader(args)
    assert status in (0, 141) and stderr == ""


def test_head_reads_the_first_lines(maxima_exe: str) -> None:
    """The issue's reproducer through a real shell pipeline."""
    proc = subprocess.run(
        f"{sys.executable} -m max2code scene examples/frozen/paddles.json --json | head -c 100; "
        f"exit ${{PIPESTATUS[0]}}", shell=True, executable="/bin/bash", cwd=ROOT, env=ENV,
        capture_output=True, text=True, timeout=600)
    assert proc.returncode in (0, 141)  # 0 when everything fitted in the pipe before head left
    assert proc.stderr == "" and len(proc.stdout) == 100


def test_help_lists_every_subcommand() -> None:
    proc = subprocess.run([sys.executable, "-m", "max2code", "--help"], capture_output=True,
                          text=True, cwd=ROOT, env=ENV)
    assert proc.returncode == 0
    assert set(SUMMARIES) == set(SUBCOMMANDS)
    for name in SUBCOMMANDS:
        assert f"\n  {name:<9} {SUMMARIES[name]}" in proc.stdout, name
        sub = subprocess.run([sys.executable, "-m", "max2code", name, "--help"],
                             capture_output=True, text=True, cwd=ROOT, env=ENV)
        assert sub.returncode == 0 and sub.stdout.startswith(f"usage: max2code {name}"), name


@pytest.mark.parametrize("command", ["build", "check", "report"])
def test_no_file_in_an_empty_folder_is_a_usage_error(command: str, tmp_path: Path) -> None:
    proc = subprocess.run([sys.executable, "-m", "max2code", command], capture_output=True,
                          text=True, cwd=tmp_path, env=ENV)
    assert proc.returncode == 2
    assert proc.stderr.splitlines()[-1] == (
        f"max2code {command}: error: no FILE.mxm given, and the current folder ({tmp_path}) has "
        f"no .mxm file; name the equations: max2code {command} FILE.mxm ...")
    assert list(tmp_path.iterdir()) == []  # nothing built, least of all the shipped equations


def test_build_without_files_builds_the_folders_equations(tmp_path: Path, maxima_exe: str) -> None:
    shutil.copy(ROOT / "equations" / "point-line.mxm", tmp_path / "mine.mxm")
    proc = subprocess.run([sys.executable, "-m", "max2code", "build", "--lang", "python"],
                          capture_output=True, text=True, cwd=tmp_path,
                          env={**ENV, "MAX2CODE_CACHE": str(tmp_path / ".cache")})
    assert proc.returncode == 0, proc.stderr
    assert sorted(p.name for p in (tmp_path / "build" / "python").iterdir()) == ["point_line.py"]
    summary = (tmp_path / "build" / "summary.md").read_text()
    assert "| mine.mxm | point_line |" in summary and "circles" not in summary
