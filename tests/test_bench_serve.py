"""bench/serve.py --bytes, the command docs/server.md quotes for every bytes ratio, runs and
its --tolerance switch reaches the rooms: with a quarter pixel (-1) the solver's held bodies
of `pile` are re-sent less often than exactly, and a scene with no held body is unchanged."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


TIMINGS = {"room CPU s"}   # columns measured in seconds of CPU: they vary from run to run


def table(*args: str) -> dict[str, list[str]]:
    """The bytes table's rows by scene (the first table the command prints), without the
    timing columns (two runs of the same stream differ there: 0.02 against 0.03 s once)."""
    out = subprocess.run([sys.executable, str(ROOT / "bench" / "serve.py"), "--bytes",
                          "--quick", *args], capture_output=True, text=True, timeout=600,
                         check=True).stdout
    header, _, *lines = out.split("\n\n")[1].splitlines()
    names = [c.strip() for c in header.strip("|").split("|")]
    keep = [k for k, name in enumerate(names) if name not in TIMINGS]
    assert len(keep) == len(names) - len(TIMINGS), names   # (the timing column is there)
    rows = {}
    for line in lines:
        cells = [c.strip() for c in line.strip("|").split("|")]
        rows[cells[0]] = [cells[k] for k in keep]
    return rows


def test_the_bytes_table_with_and_without_a_tolerance():
    exact, quarter = table(), table("--tolerance", "-1")
    assert set(exact) == set(quarter) >= {"pile", "bullet", "arena", "pinball", "tipping-box"}
    SEGMENTS = 5   # the column of segments sent
    assert int(quarter["pile"][SEGMENTS]) < int(exact["pile"][SEGMENTS])
    assert quarter["bullet"] == exact["bullet"]   # nothing held, nothing in the 50 ms wait
