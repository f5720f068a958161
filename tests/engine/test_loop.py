"""max2code.engine.loop: the example games' frame loop. Scripted input is delivered at its own
exact time (the world stepped there first), frames come at k / fps, `done` ends the run, and
live, a window's key events are delivered after the frame they came with."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from max2code.render.model import Frame


def _world(engine):
    w = engine.World()
    ball = w.add_circle((0.0, 0.0), 0.5, velocity=(1.0, 0.0))
    return w, ball


def test_script_at_its_times_frames_at_k_over_fps(engine) -> None:
    from max2code.engine import loop
    w, ball = _world(engine)
    seen: list[tuple[float, float, str]] = []
    frames_at: list[float] = []

    def deliver(item: str) -> None:   # the world is at the item's own time when it comes
        seen.append((w.time, w.pose(ball)[0], item))
        w.set_velocity(ball, (-1.0, 0.0) if item == "back" else (1.0, 0.0))

    def draw() -> Frame:
        frames_at.append(w.time)
        return Frame(w.time, ())

    script = [(0.33, "back"), (0.05, "on"), (0.33, "on")]   # out of order: sorted, stable
    frames = loop.play(w, draw, until=0.5, fps=10, script=script, deliver=deliver, keep=True)
    assert [round(t, 12) for t in frames_at] == [k / 10 for k in range(6)]
    assert [f.time for f in frames] == frames_at
    assert [(t, item) for t, _, item in seen] == [(0.05, "on"), (0.33, "back"), (0.33, "on")]
    # x follows the velocity the items set, at the items' exact times
    assert [x for _, x, _ in seen] == pytest.approx([0.05, 0.33, 0.33], abs=1e-12)
    assert w.pose(ball)[0] == pytest.approx(0.5, abs=1e-12)


def test_done_ends_the_run(engine) -> None:
    from max2code.engine import loop
    w, ball = _world(engine)
    frames = loop.play(w, lambda: Frame(w.time, ()), until=10, fps=10, keep=True,
                       done=lambda: w.pose(ball)[0] >= 0.25)
    # the frame where it came true is drawn (a game's last frame shows its goal), then no more
    assert [round(f.time, 12) for f in frames] == [0.0, 0.1, 0.2, 0.3]


def test_window_events_come_after_their_frame(engine, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("SDL_VIDEODRIVER", "dummy")
    pygame = pytest.importorskip("pygame")
    from PIL import Image

    from max2code.engine import loop
    from max2code.render.live import Window
    w, _ = _world(engine)
    now = [0.0]
    window = Window(8, 8, "test", clock=lambda: now[0], sleep=lambda dt: now.__setitem__(0, now[0] + dt))
    posts = {1: pygame.KEYDOWN, 3: pygame.QUIT}   # a key with frame 1, the window closed at 3
    shown: list[float] = []

    def picture(frame: Frame):
        shown.append(frame.time)
        kind = posts.get(len(shown) - 1)
        if kind == pygame.KEYDOWN:
            pygame.event.post(pygame.event.Event(kind, key=pygame.K_LEFT))
        elif kind is not None:
            pygame.event.post(pygame.event.Event(kind))
        return Image.new("RGB", (8, 8))

    got: list[tuple[float, str]] = []
    loop.play(w, lambda: Frame(w.time, ()), until=10, fps=4, window=window, picture=picture,
              deliver=lambda item: got.append((w.time, item)),
              from_window=lambda e: pygame.key.name(e.key) if e.type == pygame.KEYDOWN else None)
    assert shown == [0.0, 0.25, 0.5, 0.75]      # the close at frame 3 ended the loop
    assert got == [(0.25, "left")]             # delivered at its frame's time
    assert now[0] == pytest.approx(0.75)       # each frame waited for its wall time


def test_read_keys_replays_a_game_log(tmp_path: Path) -> None:
    from max2code.engine import loop
    log = tmp_path / "log.jsonl"
    records = [{"t": 0.9, "kind": "input", "type": "KEYUP", "key": "K_UP"},
               {"t": 0.5, "kind": "coin", "body": 3},
               {"t": 0.5, "type": "KEYDOWN", "key": "K_UP"}]
    log.write_text("".join(json.dumps(r) + "\n" for r in records))
    assert loop.read_keys(str(log)) == [(0.5, ("KEYDOWN", "K_UP")), (0.9, ("KEYUP", "K_UP"))]
