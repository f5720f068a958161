"""What the benchmark scripts that drive a C harness share: compiling it (gcc found once; a
failure stops the tool with the command and gcc's own message -- a harness that does not build
has nothing to measure), running a kernel harness's self-check before its timing (a harness
that prices a different computation has nothing to say), the command line a result quotes,
and publishing a result (the folder made, the file replaced whole, never half-written, and the
text echoed)."""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from max2code.machine import cpu, machine_and_date  # noqa: E402,F401  (charts' and results' machine line)
from max2code.output import write_if_changed  # noqa: E402  (temporary file, then rename)


def smoke() -> bool:
    """MAX2CODE_BENCH_SMOKE=1: run the documented command at the smallest size that still goes
    through every step (tests/test_docs.py runs the docs' bench commands so). Its figures mean
    nothing; a smoke run never writes into bench/results unless told to (results_dir)."""
    return os.environ.get("MAX2CODE_BENCH_SMOKE") == "1"


def results_dir(default: Path) -> Path:
    """Where a benchmark writes its results: MAX2CODE_BENCH_RESULTS, else the script's folder
    under bench/results (default)."""
    where = os.environ.get("MAX2CODE_BENCH_RESULTS")
    return Path(where) if where else default


def gcc(tool: str) -> str:
    """gcc's path, or the tool stops: `tool: gcc not found (run 'make setup')`."""
    path = shutil.which("gcc")
    if path is None:
        sys.exit(f"{tool}: gcc not found (run 'make setup')")
    return path


def compile_c(tool: str, what: str, args: list[str]) -> None:
    """gcc ARGS; on failure the tool stops with `tool: WHAT failed:`, the command and stderr."""
    cmd = [gcc(tool), *args]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{tool}: {what} failed:\n{' '.join(cmd)}\n{r.stderr}")


def kernel_harness(tool: str, source: Path, stdin: str, arg: str, on_mismatch: str) -> str:
    """Builds `source` (a harness that includes the C runtime's source: gcc -O2, without GSL),
    runs it with "check" -- on anything but output starting "ok" the tool stops with
    `tool: ON_MISMATCH: ` and what the check said -- then with `arg`; returns that run's
    stdout.  A run past its time limit stops the tool too, with its message."""
    root = Path(__file__).resolve().parent.parent
    with tempfile.TemporaryDirectory() as tmp:
        exe = Path(tmp) / tool
        compile_c(tool, "compiling", [
            "-O2", "-std=c11", "-Wall", "-Wextra", "-DM2C_NO_GSL", "-I",
            str(root / "runtime" / "c"), str(source), "-lm", "-o", str(exe)])
        try:
            check = subprocess.run([str(exe), "check"], input=stdin, capture_output=True,
                                   text=True, timeout=120)
            if check.returncode != 0 or not check.stdout.startswith("ok"):
                sys.exit(f"{tool}: {on_mismatch}: {(check.stdout + check.stderr).strip()}")
            r = subprocess.run([str(exe), arg], input=stdin, capture_output=True, text=True,
                               timeout=1200)
        except subprocess.TimeoutExpired as e:
            sys.exit(f"{tool}: the harness ran past {e.timeout:.0f} s ({' '.join(e.cmd)})")
        if r.returncode != 0:
            sys.exit(f"{tool}: the harness failed: {r.stderr.strip()}")
        return r.stdout


def command_line(script: str, args: argparse.Namespace, defaults: dict[str, object]) -> str:
    """`python SCRIPT` and the options among `defaults` that differ from their defaults: the
    command a result quotes, so that it can be run again as it was."""
    extra = "".join(f" --{k} {getattr(args, k)}" for k, v in defaults.items()
                    if getattr(args, k) != v)
    return f"python {script}{extra}"


def publish(out: Path, name: str, text: str) -> Path:
    """Writes `text` to out/name (out made if missing), prints it and where it went."""
    out.mkdir(parents=True, exist_ok=True)
    path = out / name
    write_if_changed(str(path), text)
    print(text)
    print(f"wrote {path}")
    return path

