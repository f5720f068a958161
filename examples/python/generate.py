"""Regenerate generated/circles.py when it is missing or older than anything in its depfile.

The make-style check a Python project can do in a few lines: max2code's -MD depfile lists the
.mxm and the files its Maxima program loads. Run max2code as $MAX2CODE (default: max2code).
"""

from __future__ import annotations

import os
import shlex
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
MXM = HERE.parent / "equations" / "circles.mxm"
OUT = HERE / "generated" / "circles.py"
DEPFILE = Path(f"{OUT}.d")


def dependencies(depfile: Path) -> list[str]:
    """The prerequisites of the depfile's first rule (Make escapes: '\\ ', '$$', '\\#', '\\:')."""
    rule = depfile.read_text().split("\n\n")[0].replace("\\\n", " ")
    words = (rule.split(": ", 1)[1].replace("\\ ", "\0").replace("$$", "$").replace("\\#", "#")
             .replace("\\:", ":"))
    return [w.replace("\0", " ") for w in words.split()]


def stale() -> bool:
    if not OUT.exists() or not DEPFILE.exists():
        return True
    built = OUT.stat().st_mtime_ns
    return any(not Path(d).exists() or Path(d).stat().st_mtime_ns > built
               for d in dependencies(DEPFILE))


def main() -> int:
    if not stale():
        print(f"{OUT.name}: up to date")
        return 0
    OUT.parent.mkdir(exist_ok=True)
    command = shlex.split(os.environ.get("MAX2CODE", "max2code"))
    print(f"{OUT.name}: regenerating", flush=True)
    result = subprocess.run([*command, "--lang=python", str(MXM), "-o", str(OUT), "-MD"])
    if result.returncode == 0:
        os.utime(OUT)  # unchanged content keeps its old time: mark it checked now
    return result.returncode


if __name__ == "__main__":
    sys.exit(main())
