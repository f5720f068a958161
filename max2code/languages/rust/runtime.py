"""What `max2code runtime --lang rust` prints: the runtime crate, as a Cargo path dependency."""

from __future__ import annotations

from ...paths import runtime_dir


def info() -> dict[str, str]:
    crate = runtime_dir("rust")
    return {"dir": str(crate), "cflags": "", "sources": str(crate / "src" / "lib.rs"),
            "libs": "", "cargo": f'max2code-runtime = {{ path = "{crate.as_posix()}" }}',
            "note": "a Cargo path dependency: the 'cargo' line goes under [dependencies]"}
