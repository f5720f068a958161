"""What `max2code runtime --lang python` prints: whether max2code_runtime imports here, and
the folder to put on PYTHONPATH when it does not."""

from __future__ import annotations

import importlib.util
from pathlib import Path

from ...paths import runtime_dir


def info() -> dict[str, str]:
    folder = runtime_dir("python")
    spec = importlib.util.find_spec("max2code_runtime")
    importable = spec is not None and spec.origin is not None
    where = str(Path(spec.origin).parent) if importable else ""  # type: ignore[union-attr, arg-type]
    return {"dir": str(folder), "cflags": "", "sources": str(folder / "max2code_runtime"),
            "libs": "", "importable": "yes" if importable else "no", "module": where,
            "note": "pure Python: installed with max2code as 'max2code_runtime', else put "
                    "'dir' on PYTHONPATH"}
