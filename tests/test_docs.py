"""Every code block of README.md and docs/*.md runs, so the documentation cannot drift.

A fenced block's info string says what it is and how it is run:

| info | run as |
|---|---|
| `sh` | a bash script (`set -euo pipefail`) in a sandbox folder holding copies of `equations/`
  and `examples/` (and `bench/` reached through a link), with this checkout's `.venv` first on
  PATH; bench scripts run in their smoke mode (MAX2CODE_BENCH_SMOKE, results into the sandbox);
  a block of `make` targets runs `make -n` on them in the checkout (the real targets are the
  whole set-up and test suite: `make test` inside the tests would run itself) |
| `python` | this interpreter, in the sandbox; a `print(...)  # EXPECTED: note` line must print
  EXPECTED exactly (the text before the first colon of the comment) |
| `mxm` | max2code generates C from it (a fragment when it has term blocks, else a module) |
| `cmake` | the CMakeLists.txt of a project with examples/cmake's main.c and circles.mxm,
  configured with max2code's package and built |
| `text` | not code (a folder tree, a message, a usage synopsis) |

A block without an info string fails the test: the author must say which it is.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest

from conftest import ROOT, require

PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
FENCE = re.compile(r"^```([^\n`]*)\n(.*?)^```[ \t]*$", re.M | re.S)
RUNNERS = ("sh", "python", "mxm", "cmake", "text")
VENV_BIN = Path(sys.executable).parent


@dataclass(frozen=True)
class Block:
    page: Path
    line: int
    info: str
    code: str

    @property
    def id(self) -> str:
        return f"{self.page.relative_to(ROOT)}:{self.line}"


def blocks() -> list[Block]:
    found = []
    for page in PAGES:
        text = page.read_text(encoding="utf-8")
        for m in FENCE.finditer(text):
            line = text.count("\n", 0, m.start()) + 1
            found.append(Block(page, line, m.group(1).strip(), m.group(2)))
    return found


ALL = blocks()


def test_every_block_says_what_it_is() -> None:
    unnamed = [b.id for b in ALL if b.info.split()[0:1] == [] or b.info.split()[0] not in RUNNERS]
    assert not unnamed, f"blocks without a known info string ({', '.join(RUNNERS)}): {unnamed}"


def test_there_are_blocks_to_run() -> None:
    # the collector itself could be wrong: the README alone has several runnable blocks
    assert sum(1 for b in ALL if b.page.name == "README.md" and b.info != "text") >= 5


@pytest.fixture()
def sandbox(tmp_path: Path) -> Path:
    for name in ("equations", "examples"):
        shutil.copytree(ROOT / name, tmp_path / name)
    (tmp_path / "bench").symlink_to(ROOT / "bench")
    return tmp_path


def _env(sandbox: Path) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV")}
    env["PATH"] = f"{VENV_BIN}{os.pathsep}{env.get('PATH', '')}"
    env["MAX2CODE_BENCH_SMOKE"] = "1"
    env["MAX2CODE_BENCH_RESULTS"] = str(sandbox / "bench-results")
    env["SDL_VIDEODRIVER"] = "dummy"
    return env


def _runnable(info: str) -> list[Block]:
    return [b for b in ALL if b.info.split()[:1] == [info]]


def _make_targets(code: str) -> list[str] | None:
    """The targets of a block whose every command is `make [target]`, else None."""
    targets = []
    for line in code.splitlines():
        command = line.split("#", 1)[0].split()
        if not command:
            continue
        if command[0] != "make" or len(command) > 2:
            return None
        targets.append(command[1] if len(command) == 2 else "all")
    return targets or None


@pytest.mark.parametrize("block", _runnable("sh"), ids=lambda b: b.id)
def test_shell_block_runs(block: Block, sandbox: Path) -> None:
    require("bash")
    targets = _make_targets(block.code)
    if targets is not None:
        for target in targets:
            proc = subprocess.run(["make", "-n", target], cwd=ROOT, capture_output=True,
                                  text=True, timeout=60)
            assert proc.returncode == 0, f"{block.id}: make -n {target}\n{proc.stderr}"
        return
    proc = subprocess.run(["bash", "-c", "set -euo pipefail\n" + block.code], cwd=sandbox,
                          env=_env(sandbox), capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, f"{block.id}:\n{block.code}\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}"


EXPECT = re.compile(r"^print\(.*\)\s*#\s*([^:]+?)\s*(?::.*)?$")


@pytest.mark.parametrize("block", _runnable("python"), ids=lambda b: b.id)
def test_python_block_runs(block: Block, sandbox: Path) -> None:
    proc = subprocess.run([sys.executable, "-c", block.code], cwd=sandbox, env=_env(sandbox),
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, f"{block.id}:\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}"
    expected = [m.group(1) for line in block.code.splitlines()
                if (m := EXPECT.match(line.strip()))]
    if expected:
        printed = proc.stdout.splitlines()
        assert printed[:len(expected)] == expected, f"{block.id}: printed {printed}"


@pytest.mark.parametrize("block", _runnable("mxm"), ids=lambda b: b.id)
def test_mxm_block_generates(block: Block, tmp_path: Path) -> None:
    require("maxima")
    source = tmp_path / "block.mxm"
    source.write_text(block.code)
    for lang, out in (("c", "block.h"), ("python", "block.py")):
        proc = subprocess.run([sys.executable, "-m", "max2code", f"--lang={lang}", str(source),
                               "-o", str(tmp_path / out)], capture_output=True, text=True,
                              timeout=300, env=_env(tmp_path))
        assert proc.returncode == 0, f"{block.id} ({lang}):\n{proc.stderr}"
        assert (tmp_path / out).stat().st_size > 0


@pytest.mark.parametrize("block", _runnable("cmake"), ids=lambda b: b.id)
def test_cmake_block_builds(block: Block, tmp_path: Path) -> None:
    cmake = require("cmake")
    require("maxima")
    project = tmp_path / "project"
    project.mkdir()
    shutil.copy(ROOT / "examples" / "cmake" / "main.c", project / "main.c")
    for name in ("circles.mxm", "motion.mac"):      # circles.mxm loads motion.mac
        shutil.copy(ROOT / "examples" / "equations" / name, project / name)
    head = "" if "project(" in block.code else \
        "cmake_minimum_required(VERSION 3.20)\nproject(doc_block C)\n"
    (project / "CMakeLists.txt").write_text(head + block.code)
    env = _env(tmp_path)
    package = subprocess.run([sys.executable, "-m", "max2code", "runtime", "--cmake-dir"],
                             capture_output=True, text=True, check=True, env=env).stdout.strip()
    for args in ([cmake, "-S", str(project), "-B", str(project / "build"),
                  f"-Dmax2code_DIR={package}"], [cmake, "--build", str(project / "build")]):
        proc = subprocess.run(args, capture_output=True, text=True, timeout=600, env=env)
        assert proc.returncode == 0, f"{block.id}: {' '.join(args)}\n{proc.stdout}\n{proc.stderr}"
