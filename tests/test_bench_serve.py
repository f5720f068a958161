"""bench/serve.py --bytes, the command docs/server.md quotes for every bytes ratio, runs and
its --tolerance switch reaches the rooms: with a quarter pixel (-1) the solver's held bodies
of `pile` are re-sent less often than exactly, and a scene with no held body is unchanged."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def table(*args: str) -> dict[str, list[str]]:
    """The bytes table's rows by scene (the first table the command prints)."""
    out = subprocess.run([sys.executable, str(ROOT / "bench" / "serve.py"), "--bytes",
                          "--quick", *args], capture_output=True, text=True, timeout=600,
                         check=True).stdout
    rows = {}
    for line in out.split("\n\n")[1].splitlines()[2:]:
        cells = [c.strip() for c in line.strip("|").split("|")]
        rows[cells[0]] = cells
    return rows


def test_the_bytes_table_with_and_without_a_tolerance():
    exact, quarter = table(), table("--tolerance", "-1")
    assert set(exact) == set(quarter) >= {"pile", "bullet", "arena", "pinball", "tipping-box"}
    SEGMENTS = 5   # the column of segments sent
    assert int(quarter["pile"][SEGMENTS]) < int(exact["pile"][SEGMENTS])
    assert quarter["bullet"] == exact["bullet"]   # nothing held, nothing in the 50 ms wait
