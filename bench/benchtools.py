"""What the benchmark scripts that drive a C harness share: compiling it (gcc found once; a
failure stops the tool with the command and gcc's own message -- a harness that does not build
has nothing to measure) and publishing a result (the folder made, the file replaced whole,
never half-written, and the text echoed)."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from max2code.output import write_if_changed  # noqa: E402  (temporary file, then rename)


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


def publish(out: Path, name: str, text: str) -> Path:
    """Writes `text` to out/name (out made if missing), prints it and where it went."""
    out.mkdir(parents=True, exist_ok=True)
    path = out / name
    write_if_changed(str(path), text)
    print(text)
    print(f"wrote {path}")
    return path
