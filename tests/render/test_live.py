"""The optional window: shows the raster's pixels when pygame is there, and says how to get it when
it is not (without failing the caller)."""

from __future__ import annotations

import sys

import pytest

from conftest import require_module as need
from max2code.render import Body, Circle, Frame, Pose, RenderUnavailable, Style, View
from max2code.render import live

BODIES = [Body(Circle(1.0), Style(fill="#ff0000"))]
VIEW = View(0, 0, 8, 6, width=160, height=120)


def frames(n: int):
    for i in range(n):
        yield Frame(i / 10, (Pose(1 + 0.5 * i, 3, i),))


def test_without_pygame_the_window_is_skipped_cleanly(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "pygame", None)        # import pygame now raises ImportError
    assert live.available() is False
    with pytest.raises(RenderUnavailable, match=r"pip install 'max2code\[live\]'"):
        live.show(BODIES, frames(2), VIEW)


def test_window_shows_every_frame_at_its_time(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("SDL_VIDEODRIVER", "dummy")
    pygame = need("pygame")
    need("PIL")
    from max2code.render.raster import frame_image
    now = [100.0]
    waits: list[float] = []

    def sleep(dt: float) -> None:
        waits.append(dt)
        now[0] += dt

    shown_pixels = []
    flip = pygame.display.flip

    def capture() -> None:
        shown_pixels.append(pygame.image.tobytes(pygame.display.get_surface(), "RGB"))
        flip()

    monkeypatch.setattr(pygame.display, "flip", capture)
    assert live.available()
    assert live.show(BODIES, frames(4), VIEW, fps=10, clock=lambda: now[0], sleep=sleep) == 4
    # drawing took no (fake) time: it waited 0.1 s before each frame after the first
    assert waits == pytest.approx([0.1, 0.1, 0.1])
    want = [frame_image(BODIES, f, VIEW).tobytes() for f in frames(4)]
    assert shown_pixels == want


def test_closing_the_window_ends_the_show(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("SDL_VIDEODRIVER", "dummy")
    pygame = need("pygame")
    real_get = pygame.event.get
    calls = [0]

    def get():
        calls[0] += 1
        real_get()
        return [pygame.event.Event(pygame.QUIT)] if calls[0] == 2 else []

    monkeypatch.setattr(pygame.event, "get", get)
    assert live.show(BODIES, frames(10), VIEW, fps=1000) == 2


def test_no_display_is_a_note_not_a_hidden_window(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without a display pygame 2 falls back to SDL's offscreen driver and "shows" every frame
    to nobody, in real time: that is no window.  (A driver the user chose is obeyed: the tests
    above choose "dummy".)"""
    need("pygame")
    for var in ("SDL_VIDEODRIVER", "DISPLAY", "WAYLAND_DISPLAY"):
        monkeypatch.delenv(var, raising=False)
    with pytest.raises(RenderUnavailable, match="no display"):
        live.show(BODIES, frames(2), VIEW)
