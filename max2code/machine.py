"""What a chart or a measured result names as where and when it was made: the CPU's model
and today's date (UTC)."""

from __future__ import annotations

import datetime
import os
import platform
from pathlib import Path


def cpu() -> str:
    """The CPU's model name (from /proc/cpuinfo), else the architecture."""
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.machine() or "unknown machine"


def today() -> str:
    return datetime.datetime.now(datetime.timezone.utc).date().isoformat()


def machine_and_date() -> str:
    """'CPU model, N cores, YYYY-MM-DD'."""
    return f"{cpu()}, {os.cpu_count()} cores, {today()}"
