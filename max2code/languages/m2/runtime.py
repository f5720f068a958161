"""What `max2code runtime --lang m2` prints: the definition module's folder, gm2's flags, and
the C runtime with gm2's ISO library to link."""

from __future__ import annotations

import shutil
import subprocess

from ...paths import runtime_dir
from ..c import runtime as c_runtime


def iso_libs() -> list[str]:
    """gm2's ISO library folder, as DESIGN.md measured: -L<m2iso> -lm2iso -lpthread."""
    gm2 = shutil.which("gm2")
    folder = "$(gm2 -print-file-name=m2/m2iso)"
    if gm2:
        try:
            found = subprocess.run([gm2, "-print-file-name=m2/m2iso"], capture_output=True,
                                   text=True, timeout=30).stdout.strip()
            folder = found or folder
        except (OSError, subprocess.SubprocessError):
            pass
    return [f"-L{folder}", "-lm2iso", "-lpthread"]


def info() -> dict[str, str]:
    m2 = runtime_dir("m2")
    return {"dir": str(m2), "cflags": f"-fiso -I{m2}", "sources": c_runtime.source(),
            "libs": " ".join(iso_libs() + c_runtime.LIBS),
            "note": "Max2codeRoots.def binds the C runtime: compile the C source with gcc "
                    "and link it; compile the generated .mod with gm2 -fiso -fcpp"}
