"""`max2code sim`: runs a scene, writes the event log (the same bytes every run), a summary."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

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


def test_until_and_fps_must_be_finite(engine, tmp_path: Path) -> None:
    """--until inf used to step the core to an infinite time (a crash on its empty timer
    list); --fps inf asked for endless frames at t = 0.  Both, and a run asking for more frames
    than are kept, are errors before any step."""
    scene = tmp_path / "drop.toml"
    scene.write_text(SCENE)
    for args in (["--until", "inf"], ["--until", "nan"], ["--fps", "inf", "--png", "x.png"],
                 ["--until", "1e6", "--fps", "30", "--png", str(tmp_path / "x.png")]):
        proc = sim(str(scene), *args)
        assert proc.returncode == 1, (args, proc.returncode, proc.stderr)
        assert "error:" in proc.stderr and "Traceback" not in proc.stderr, proc.stderr
    assert not (tmp_path / "x.png").exists()


def test_the_api_refuses_an_infinite_step(engine) -> None:
    w = engine.World()
    w.add_circle((0.0, 0.0), 0.1, velocity=(1.0, 0.0))
    for t in (float("inf"), float("nan")):
        try:
            w.step_to(t)
        except engine.EngineError as exc:
            assert "finite" in str(exc)
        else:
            raise AssertionError(f"step_to({t}) was accepted")
    assert w.step_to(1.0) == [] and w.pose(0)[0] == 1.0  # the world still steps


@pytest.mark.parametrize("step", [0.0, 1 / 240])
def test_max_events_counts_the_whole_step(engine, step: float) -> None:
    """max_events limits one step, whose core calls return each time the binding's buffer
    fills (about a thousand events): the count used to start again at each of them, so that no
    limit above that ever applied. The contact solver's ticks are no events (they counted, and
    a step of exactly the limit failed)."""
    def pile(limit: int):
        w = engine.World(gravity=(0.0, -9.81), max_events=limit, contact_step=step)
        w.add_segment((-1.0, 0.0), (1.0, 0.0))
        w.add_segment((-1.0, 0.0), (-1.0, 3.0))
        w.add_segment((1.0, 0.0), (1.0, 3.0))
        for k in range(40):
            w.add_circle((-0.8 + 0.2 * (k % 9), 0.2 + 0.25 * (k // 9)), 0.09, restitution=0.9)
        return w
    from max2code.engine.world import BUFFER

    free = pile(0)
    reported = len(free.step_to(3.0))
    total = free.stats()["events"]  # every event processed, reported or not
    assert reported > BUFFER  # the step took more than one call of the core
    assert len(pile(total).step_to(3.0)) == reported  # exactly the limit: allowed
    w = pile(total - 1)
    try:
        w.step_to(3.0)
    except engine.EngineError as exc:
        assert "max_events" in str(exc)
    else:
        raise AssertionError("a step of more than max_events events went through")


def test_a_failed_picture_leaves_the_event_log(engine, tmp_path: Path) -> None:
    scene = tmp_path / "drop.toml"
    scene.write_text(SCENE)
    log = tmp_path / "events.jsonl"
    log.write_text("previous\n")
    proc = sim(str(scene), "--events", str(log), "--gif", str(tmp_path / "no" / "such" / "x.gif"))
    assert proc.returncode == 1 and "error" in proc.stderr
    assert log.read_text() == "previous\n"


def test_a_single_picture_shows_the_state_at_until(engine, tmp_path: Path) -> None:
    """--svg and --png draw the state at T, a frame of its own when T is not a frame time."""
    scene = tmp_path / "drop.toml"
    scene.write_text(SCENE)
    svg = tmp_path / "x.svg"
    proc = sim(str(scene), "--until", "0.55", "--fps", "10", "--svg", str(svg))
    assert proc.returncode == 0, proc.stderr
    assert "t = 0.550 s" in svg.read_text()


def test_events_to_standard_output_through_a_pipe(engine, tmp_path: Path) -> None:
    """/dev/stdout names the descriptor: written into a pipe (realpath named a pipe that does
    not exist), and into a shell's redirection without cutting off the summary after it."""
    scene = tmp_path / "drop.toml"
    scene.write_text(SCENE)
    proc = subprocess.run(f"{sys.executable} -m max2code sim {scene} --events /dev/stdout | cat",
                          shell=True, capture_output=True, text=True, cwd=ROOT, timeout=600)
    assert proc.returncode == 0 and proc.stdout.startswith('{"t":'), proc.stderr
    out = tmp_path / "out.txt"
    proc = subprocess.run(f"{sys.executable} -m max2code sim {scene} --events /dev/stdout > {out}",
                          shell=True, capture_output=True, text=True, cwd=ROOT, timeout=600)
    assert proc.returncode == 0, proc.stderr
    lines = out.read_text().splitlines()
    assert lines[0].startswith('{"t":') and lines[-1].startswith("drop: 2 bodies"), lines


def test_a_failed_or_abandoned_step_ends_its_count(engine) -> None:
    """max_events counts one step: after a step that failed on it, or one a raising callback
    left unfinished, the next step counts from zero (a reviewer's case: a ball between two walls,
    about 6 events a second, max_events 4)."""
    def make():
        w = engine.World(max_events=4)
        w.add_segment((-1.0, -5.0), (-1.0, 5.0))
        w.add_segment((1.0, -5.0), (1.0, 5.0))
        w.add_circle((0.0, 0.0), 0.1, velocity=(10.0, 0.0))
        return w

    w = make()
    try:
        w.step_to(1.0)
    except engine.EngineError:
        pass
    else:
        raise AssertionError("6 events in a step of max_events 4")
    assert len(w.step_to(w.time + 0.5)) >= 2

    class Stop(Exception):
        pass

    w = make()
    seen = []

    def stop_at_the_third(world, ev) -> None:
        seen.append(ev)
        if len(seen) == 3:  # (once)
            raise Stop

    w.on_collision(stop_at_the_third)
    try:
        w.step_to(1.0)
    except Stop:
        pass
    w.step_to(w.time + 0.5)  # a fresh step: within the limit, whatever the last one counted
    assert len(seen) > 3
