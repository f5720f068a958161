"""A game's frame loop: the world stepped to each frame's time, scripted input delivered at its
own exact time in between, and, live, each frame shown in a window at its wall-clock time with
the window's input delivered at the next frame.

The example games (examples/games) share it, so that a headless scripted run and a live one
step the world the same way: only where an input's time comes from differs (the script's
exact time, or the frame after the key was pressed).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any, TypeVar

from ..render.live import Closed, Window
from ..render.model import Frame

T = TypeVar("T")


def play(world: Any, draw: Callable[[], Frame], *, until: float, fps: float,
         script: Sequence[tuple[float, T]] = (), deliver: Callable[[T], None] = lambda _: None,
         done: Callable[[], bool] = lambda: False, keep: bool = False,
         window: Window | None = None, picture: Callable[[Frame], Any] | None = None,
         from_window: Callable[[Any], T | None] = lambda _: None) -> list[Frame]:
    """Frame k at k / fps for k = 0, 1, ... while k / fps <= until and not done(); `script`'s
    (time, input) pairs, in time order, are delivered at their times (world stepped there
    first). With a `window`, `picture(frame)` is shown at the frame's time and each window
    event that `from_window` maps to an input is delivered after it; a closed window ends the
    loop. Returns the frames when `keep`."""
    frames: list[Frame] = []
    queue = sorted(script, key=lambda item: item[0])
    k = 0
    try:
        while k / fps <= until and not done():
            t = k / fps
            while queue and queue[0][0] <= t:
                tk, item = queue.pop(0)
                world.step_to(tk)
                deliver(item)
            world.step_to(t)
            frame = draw()
            if keep:
                frames.append(frame)
            if window is not None and picture is not None:
                for event in window.show(picture(frame), t):
                    item = from_window(event)
                    if item is not None:
                        deliver(item)
            k += 1
    except Closed:
        pass
    finally:
        if window is not None:
            window.close()
    return frames


def read_keys(path: str) -> list[tuple[float, tuple[str, str]]]:
    """The example games' key scripts: JSON lines {"t": 0.5, "type": "KEYDOWN", "key": "K_UP"}
    as their event logs write them (a record of another "kind" is skipped, so that a game's log
    replays): (time, (type, key)) in time order."""
    import json

    out = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.strip():
                rec = json.loads(line)
                if rec.get("kind", "input") == "input":
                    out.append((float(rec["t"]), (rec["type"], rec["key"])))
    return sorted(out, key=lambda r: r[0])
