"""`max2code pge`: scripted input, replays, errors located in the game, nothing written on failure."""

from __future__ import annotations

import json
import os
import re
from pathlib import Path

import pytest

from .conftest import CORPUS, pge_run

GAME = '''\
import pge, sys
from pygame.locals import *

white = pge.rgb(1, 1, 1)
pge.box(0, 0, 1, 0.02, white).fix()
ball = pge.circle(0.5, 0.5, 0.05, white).mass(1)
hits = []

def bounced(o, e):
    hits.append(e.collision_between())
    if len(hits) == 2:
        o.rm()

def key(e):
    if e.key == K_UP:
        ball.put_yvel(ball.get_yvel() + 3)

ball.on_collision(bounced)
pge.register_handler(key, [KEYDOWN])
pge.display_set_mode([800, 800])
pge.gravity()
pge.run(3)
print("hits", len(hits), ball.get_ypos())
'''


def write_game(tmp: Path, text: str = GAME) -> Path:
    p = tmp / "game.py"
    p.write_text(text)
    return p


def test_a_game_written_here_runs_and_its_callbacks_remove_at_the_hit(tmp_path: Path) -> None:
    r, log = pge_run(tmp_path, str(write_game(tmp_path)))
    assert r.returncode == 0, r.stderr
    hits = [e for e in log if e["kind"] == "collision"]
    # a fall from 0.45 (to touch) under 9.81: t = sqrt(2 * 0.43 / 9.81) for the first hit
    assert hits[0]["t"] == pytest.approx((2 * (0.5 - 0.05 - 0.02) / 9.81) ** 0.5, rel=1e-9)
    # elastic: the second hit a full bounce later, then the ball is gone (no third)
    assert hits[1]["t"] == pytest.approx(3 * hits[0]["t"], rel=1e-9)
    assert len(hits) == 2
    assert [e for e in log if e["kind"] == "rm"] == [{"t": hits[1]["t"], "kind": "rm", "object": "circle-1"}]
    assert r.stdout.startswith("hits 2 ")


def test_scripted_keys_reach_the_handler_at_their_time_and_a_log_replays(tmp_path: Path) -> None:
    game = write_game(tmp_path)
    script = tmp_path / "keys.jsonl"
    script.write_text('{"t": 0.1, "type": "KEYDOWN", "key": "K_UP"}\n'
                      '{"t": 0.2, "type": "KEYDOWN", "key": "K_DOWN"}\n')
    r, log = pge_run(tmp_path, str(game), "--input", str(script))
    assert r.returncode == 0, r.stderr
    keys = [e for e in log if e["kind"] == "input"]
    assert [(e["t"], e["key"]) for e in keys] == [(0.1, "K_UP"), (0.2, "K_DOWN")]
    first = [e for e in log if e["kind"] == "collision"][0]
    # the kick at 0.1 (vy = -0.981 + 3 = 2.019 from y = 0.5 - 0.981 * 0.1 / 2)
    y1, v1, h = 0.5 - 9.81 * 0.01 / 2, -0.981 + 3.0, 0.5 - 0.07
    y1 -= 0.07
    t = 0.1 + (v1 + (v1 * v1 + 2 * 9.81 * y1) ** 0.5) / 9.81
    assert first["t"] == pytest.approx(t, rel=1e-9)
    # the log, as input, replays the same game
    again = tmp_path / "again"
    again.mkdir()
    r2, log2 = pge_run(again, str(game), "--input", str(tmp_path / "log.jsonl"))
    assert r2.returncode == 0 and log2 == log


@pytest.mark.parametrize("line, message", [
    ('{"t": 1, "type": "KEYDOWN", "key": "K_NOPE"}', r"input\.jsonl:1:1: error: unknown key 'K_NOPE'"),
    ('{"t": -1, "type": "KEYDOWN", "key": "K_UP"}', r"input\.jsonl:1:1: error: 't' must be a finite"),
    ('{"t": 1, "type": "JOYSTICK"}', r"input\.jsonl:1:1: error: 'type' must be one of"),
    ('{"t": 1, "type": "MOUSEBUTTONDOWN", "pos": [1], "button": 1}', r"'pos' must be \[x, y\]"),
    ('{"t": 1,', r"input\.jsonl:1:\d+: error: not JSON"),
])
def test_bad_input_scripts_are_located_errors_and_touch_no_output(tmp_path: Path, line: str,
                                                                  message: str) -> None:
    game = write_game(tmp_path)
    (tmp_path / "input.jsonl").write_text(line + "\n")
    (tmp_path / "log.jsonl").write_text("old\n")
    env_log = tmp_path / "log.jsonl"
    import subprocess
    import sys
    r = subprocess.run([sys.executable, "-m", "max2code", "pge", str(game), "--headless",
                        "--input", "input.jsonl", "--events", str(env_log)], cwd=tmp_path,
                       capture_output=True, text=True, env=dict(os.environ, SDL_VIDEODRIVER="dummy"))
    assert r.returncode == 1
    assert re.search(message, r.stderr), r.stderr
    assert env_log.read_text() == "old\n"


@pytest.mark.parametrize("call, name", [("pge.play('boing.wav')", "play"),
                                        ("pge.draw_collision(True, True)", r"draw_collision\(predict=True\)"),
                                        ("pge.message('hi')", "message")])
def test_unsupported_calls_are_errors_naming_the_call_at_its_place(tmp_path: Path, call: str,
                                                                   name: str) -> None:
    game = write_game(tmp_path, "import pge\n\nx = 1\n" + "    " * 0 + f"y = {call}\n")
    r, log = pge_run(tmp_path, str(game))
    assert r.returncode == 1 and log is None
    assert re.fullmatch(rf".*game\.py:4:5: error: unsupported: {name} \(.*\)\n", r.stderr, re.S), r.stderr


def test_a_moving_object_without_mass_is_an_error_naming_where_it_was_made(tmp_path: Path) -> None:
    game = write_game(tmp_path, "import pge\nw = pge.rgb(1, 1, 1)\nb = pge.box(0.1, 0.1, 0.2, 0.2, w)\n"
                                "pge.run(1)\n")
    r, _ = pge_run(tmp_path, str(game))
    assert r.returncode == 1
    assert "game.py:4:1: error: box-0 (made at " in r.stderr and "game.py:3) is not fixed and has no mass" in r.stderr


def test_the_games_own_exit_status_and_exceptions(tmp_path: Path) -> None:
    r, log = pge_run(tmp_path, str(write_game(tmp_path, "import pge, sys\npge.at_time(0.5, lambda e, p: sys.exit(3))\npge.run(2)\n")))
    assert r.returncode == 3 and log[-1] == {"t": 0.5, "kind": "timer", "id": 1}
    r, _ = pge_run(tmp_path, str(write_game(tmp_path, "import pge\n\ndef f(e, p):\n    1 / 0\npge.at_time(1, f)\npge.run(2)\n")))
    assert r.returncode == 1 and "game.py:4:5: error: ZeroDivisionError: division by zero" in r.stderr


def test_timers_follow_slow_down_and_cancel(tmp_path: Path) -> None:
    game = write_game(tmp_path, "import pge\npge.slow_down(4)\na = pge.at_time(2, lambda e, p: print('a', e.get_timer_id()))\n"
                                "b = pge.at_time(1, lambda e, p: print('b'))\npge.at_cancel(b)\npge.run(1)\n")
    r, log = pge_run(tmp_path, str(game))
    assert r.returncode == 0, r.stderr
    assert r.stdout == "a 1\n"
    assert [e for e in log if e["kind"] == "timer"] == [{"t": 0.5, "kind": "timer", "id": 1}]


def test_pictures_of_a_corpus_game(tmp_path: Path) -> None:
    if not CORPUS.is_dir():
        pytest.skip("no corpus")
    from PIL import Image
    gif = tmp_path / "rot.gif"
    r, _ = pge_run(tmp_path, str(CORPUS / "examples" / "rotation-rotation.py"), "--gif", str(gif),
                   "--fps", "20", "--size", "100")
    assert r.returncode == 0, r.stderr
    im = Image.open(gif)
    assert im.size == (100, 100) and im.n_frames > 10
    im.seek(0)
    rgb = im.convert("RGB")
    assert rgb.getpixel((50, 50)) == (0, 0, 0)            # PGE's black
    assert rgb.getpixel((44, 65)) == (255, 0, 0)           # the fixed red box at (0.39..0.49, 0.3..0.4)
