"""Input events in the event queue (issue 35 item 3): keys and the mouse at their time, from a
JSON-lines script or live, with the same run for the same timed input."""

from __future__ import annotations

import pytest

from max2code.engine.inputs import Input, InputError, parse_script, read_script, write_script

SCRIPT = """\
{"t": 0.25, "type": "key_down", "key": "right"}
{"t": 1.1, "type": "key_up", "key": "right"}
{"t": 1.5, "type": "key_down", "key": "left"}
{"t": 2.75, "type": "mouse_down", "pos": [0.5, 1.0], "button": 1}
{"t": 3.0, "type": "key_up", "key": "left"}
"""


def _game(engine):
    """A paddle steered by the arrow keys under balls falling from a ceiling; a click stops
    everything (a timer in the log shows when)."""
    w = engine.World(gravity=(0.0, -4.0))
    paddle = w.add_polygon([(-0.6, -0.1), (0.6, -0.1), (0.6, 0.1), (-0.6, 0.1)], kind="kinematic")
    w.add_segment((-4.0, 6.0), (4.0, 6.0))
    for k in range(5):
        w.add_circle((-2.0 + k, 3.0 + 0.3 * k), 0.15, velocity=(0.2 * k, 0.0))
    speed = {"right": 2.0, "left": -2.0}

    def on_input(world, ev):
        inp = ev.data[0]
        if inp.type == "key_down":
            world.set_velocity(paddle, (speed[inp.key], 0.0))
        elif inp.type == "key_up":
            world.set_velocity(paddle, (0.0, 0.0))
        else:
            world.add_timer(world.time + 0.125)

    w.on_input(on_input)
    return w


def _log(events):
    return [(e.time, e.kind, e.a, e.b, e.normal, e.speed, e.impulse) for e in events]


def test_script_inputs_happen_at_their_time(engine) -> None:
    w = _game(engine)
    for inp in parse_script(SCRIPT):
        w.add_input(inp)
    events = w.step_to(5.0)
    inputs = [(e.time, e.data[0].type) for e in events if e.kind == "input"]
    assert inputs == [(0.25, "key_down"), (1.1, "key_up"), (1.5, "key_down"),
                      (2.75, "mouse_down"), (3.0, "key_up")]
    assert any(e.kind == "timer" and e.time == 2.875 for e in events)
    # the paddle moved right 0.85 s at 2, left 1.5 s at 2: x = 1.7 - 3.0
    assert w.pose(0)[0] == pytest.approx(1.7 - 3.0, rel=1e-14)
    assert any(e.kind == "collision" and 0 in (e.a, e.b) for e in events)


def test_replay_of_a_live_session_gives_the_same_log(engine, tmp_path) -> None:
    """Live: inputs arrive between frames at the world's time; their record, replayed
    headless from a file, gives the same events bit for bit."""
    live = _game(engine)
    log = []
    frame = 1 / 60
    arrivals = {15: Input(0.0, "key_down", "right"), 66: Input(0.0, "key_up", "right"),
                90: Input(0.0, "key_down", "left"), 165: Input(0.0, "mouse_down", pos=(0.5, 1.0), button=1)}
    for k in range(1, 301):
        log += live.step_to(k * frame)
        if k in arrivals:
            a = arrivals[k]
            live.add_input(Input(live.time, a.type, a.key, a.pos, a.button))
    path = tmp_path / "session.jsonl"
    write_script(live.inputs, path)
    replay = _game(engine)
    for inp in read_script(path):
        replay.add_input(inp)
    assert _log(replay.step_to(300 * frame)) == _log(log)


@pytest.mark.parametrize("line,words", [
    ('{"t": -1, "type": "key_down", "key": "a"}', "'t' must be"),
    ('{"t": 1, "type": "key_press", "key": "a"}', "'type' must be"),
    ('{"t": 1, "type": "key_down"}', "needs 'key'"),
    ('{"t": 1, "type": "mouse_down", "pos": [1]}', "needs 'pos'"),
    ('{"t": 1, "type": "key_down", "key": "a", "when": 2}', "unknown field 'when'"),
    ('{"t": 1, "type": ', "not JSON"),
    ('[1, 2]', "JSON object"),
])
def test_bad_scripts_are_located_errors(line: str, words: str) -> None:
    with pytest.raises(InputError) as info:
        parse_script('{"t": 0, "type": "key_up", "key": "a"}\n' + line + "\n", "play.jsonl")
    assert str(info.value).startswith("play.jsonl:2:") and words in str(info.value)
    assert ": error: " in str(info.value)
