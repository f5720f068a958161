"""Which C sources the cffi backend was built from (build.py writes the digest, _cbackend
checks it): shared by both so that neither imports the other."""
from __future__ import annotations

import hashlib
from pathlib import Path

STAMP = Path(__file__).resolve().parent / "_roots_c.stamp"


def source_digest(src: Path) -> str:
    h = hashlib.sha256()
    for name in ("max2code_roots.c", "max2code_roots.h"):
        h.update((src / name).read_bytes())
    return h.hexdigest()
