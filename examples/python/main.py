"""One fixed scene: when do the two circles touch? (See ../README.md for the scene.)

Run `python generate.py` first; it writes generated/circles.py.
"""

from __future__ import annotations

import os
import shlex
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent / "generated"))
try:
    import max2code_runtime  # noqa: F401 - installed with max2code
except ImportError:  # a checkout: ask max2code where its Python runtime lives
    command = shlex.split(os.environ.get("MAX2CODE", "max2code"))
    where = subprocess.run([*command, "runtime", "--lang", "python", "--dir"], check=True,
                           capture_output=True, text=True).stdout.strip()
    sys.path.insert(0, where)

import circles  # noqa: E402 - generated

# x1, y1, vx1, vy1, ax1, ay1, r1, x2, y2, vx2, vy2, ax2, ay2, r2
P = (0, 0, 1, 0, 0.5, 0, 1, 10, 0, -1, 0, 0, 0, 0.5)

t = circles.first_root(P, 100.0)
if t is None:
    print("no collision")
    sys.exit(1)
print(f"collision at t = {t!r}")
