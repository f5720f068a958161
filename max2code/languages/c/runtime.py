"""What `max2code runtime --lang c` prints: the C runtime's folder, source and libraries."""

from __future__ import annotations

from ...paths import runtime_dir

LIBS = ["-lgsl", "-lgslcblas", "-lm"]


def source() -> str:
    return str(runtime_dir("c") / "max2code_roots.c")


def info() -> dict[str, str]:
    c_dir = runtime_dir("c")
    return {"dir": str(c_dir), "cflags": f"-I{c_dir}", "sources": source(), "libs": " ".join(LIBS),
            "note": "compile the source into the program; the generated header includes "
                    "max2code_roots.h"}
