"""`max2code sim`: runs a scene, writes the event log (the same bytes every run), a summary."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from conftest import ROOT

SCENE = """\
name = "drop"
gravity = [0, -10]
until = 2

[[bodies]]
name = "floor"
kind = "static"
shape = "segment"
points = [[-5, 0], [5, 0]]

[[bodies]]
name = "ball"
shape = "circle"
position = [0, 5.5]
radius = 0.5
"""


def sim(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "max2code", "sim", *args], capture_output=True,
                          text=True, cwd=ROOT, timeout=600)


def test_sim_event_log(engine, tmp_path: Path) -> None:
    scene = tmp_path / "drop.toml"
    scene.write_text(SCENE)
    log = tmp_path / "events.jsonl"
    proc = sim(str(scene), "--events", str(log), "--json")
    assert proc.returncode == 0, proc.stderr
    lines = [json.loads(x) for x in log.read_text().splitlines()]
    # falls 5 m: t = 1 exactly (g = 10), then elastic bounces every 2 s
    assert len(lines) == 1
    rec = lines[0]
    assert rec["kind"] == "collision" and rec["a"] == "ball" and rec["b"] == "floor"
    assert abs(rec["t"] - 1.0) <= 4.5e-16 and rec["normal"] == [0.0, -1.0]
    assert abs(rec["speed"] - 10.0) <= 1e-14
    mass = 3.141592653589793 * 0.25
    assert abs(rec["impulse"] - 2 * 10.0 * mass) <= 1e-13
    summary = json.loads(proc.stdout)
    assert summary["collisions"] == 1 and abs(summary["energy_drift"]) < 1e-14
    first = log.read_bytes()
    assert sim(str(scene), "--events", str(log), "--until", "2").returncode == 0
    assert log.read_bytes() == first


def test_sim_until_option(engine, tmp_path: Path) -> None:
    scene = tmp_path / "drop.toml"
    scene.write_text(SCENE)
    log = tmp_path / "e.jsonl"
    assert sim(str(scene), "--until", "6", "--events", str(log)).returncode == 0
    times = [json.loads(x)["t"] for x in log.read_text().splitlines()]
    assert [round(t, 12) for t in times] == [1.0, 3.0, 5.0]
