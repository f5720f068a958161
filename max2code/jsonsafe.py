"""JSON that every reader accepts: no NaN, no Infinity."""

from __future__ import annotations

import math


def json_safe(value):
    """value with every float that is not finite replaced by None: JSON has no NaN or
    Infinity (Python's json writes them, and other readers refuse the file), so a quantity
    that overflowed reads as null (the summary's energies of a run that blew up, say)."""
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {k: json_safe(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [json_safe(v) for v in value]
    return value
