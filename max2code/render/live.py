"""A live window, when pygame is installed: frames are shown as they come, at their own times.

pygame is optional (pip install 'max2code[live]'); without it `available()` is False and `show`
raises RenderUnavailable with the install line, so a caller can skip the window and go on.
The pictures are the raster's (the same pixels as the PNG and GIF outputs); pygame only puts them
on the screen and reports a closed window or Escape, which end the show early.
"""

from __future__ import annotations

import importlib
import os
import time
from collections.abc import Callable, Iterable, Sequence

from .model import Body, Frame, View
from .write import RenderUnavailable, check_fps, drawing_modules


# SDL's video drivers that show nothing, which pygame 2 falls back to without a display
HEADLESS = ("offscreen", "dummy")


def _pygame():
    os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")  # no greeting on our standard output
    try:
        return importlib.import_module("pygame")
    except ImportError:
        return None


def available() -> bool:
    return _pygame() is not None


class Closed(Exception):
    """The window was closed (or Escape pressed): the show is over."""


class Window:
    """A pygame window that shows images at given wall-clock offsets and hands back the input
    events that came meanwhile: the one place where a frame meets the screen (`show`, the
    example games).  Opened at the first image; late images are shown at once, never skipped.
    `clock` and `sleep` are injectable so that a test can run it on a fake clock."""

    def __init__(self, width: int, height: int, title: str,
                 clock: Callable[[], float] = time.monotonic,
                 sleep: Callable[[float], None] = time.sleep) -> None:
        self.size = (width, height)
        self.title = title
        self.clock = clock
        self.sleep = sleep
        self.start: float | None = None
        self.screen = None

    def open(self) -> None:
        """Open the window (RenderUnavailable without pygame or a display)."""
        pygame = _pygame()
        if pygame is None:
            raise RenderUnavailable("the live window needs pygame: pip install 'max2code[live]'")
        try:
            pygame.display.init()
            driver = pygame.display.get_driver()
            if driver in HEADLESS and not os.environ.get("SDL_VIDEODRIVER"):
                # SDL fell back to drawing nowhere (no display): say so, rather than spend the
                # run's wall time on a window nobody sees (a driver the user chose is obeyed)
                raise pygame.error(f"no display (SDL's video driver fell back to '{driver}')")
            self.screen = pygame.display.set_mode(self.size)
        except pygame.error as exc:  # no display to open a window on
            pygame.display.quit()
            raise RenderUnavailable(f"pygame cannot open a window: {exc}") from None
        pygame.display.set_caption(self.title)
        self.start = self.clock()

    def show(self, image, at: float) -> list:
        """Show a PIL RGB image `at` seconds of wall time after the first; the pygame events
        that came (key and mouse), or Closed on a closed window or Escape."""
        pygame = _pygame()
        if self.screen is None:
            self.open()
        surface = pygame.image.frombuffer(image.tobytes(), image.size, "RGB")
        wait = self.start + at - self.clock()
        if wait > 0:
            self.sleep(wait)
        self.screen.blit(surface, (0, 0))
        pygame.display.flip()
        events = []
        for event in pygame.event.get():
            if event.type == pygame.QUIT or (event.type == pygame.KEYDOWN
                                             and event.key == pygame.K_ESCAPE):
                raise Closed()
            events.append(event)
        return events

    def close(self) -> None:
        if self.screen is not None:
            _pygame().display.quit()
            self.screen = None


def show(bodies: Sequence[Body], frames: Iterable[Frame], view: View, fps: float = 60.0,
         title: str = "max2code sim", clock: Callable[[], float] = time.monotonic,
         sleep: Callable[[float], None] = time.sleep) -> int:
    """Show frames in a window, frame i at i / fps seconds of wall time after the first (late
    frames are shown at once, never skipped, so the picture is right even when drawing is slow).
    Returns the number of frames shown: fewer than given when the window was closed."""
    raster, _ = drawing_modules()
    fps = check_fps(fps)
    window = Window(view.width, view.height, title, clock, sleep)
    window.open()
    shown = 0
    try:
        for i, frame in enumerate(frames):
            image = raster.frame_image(bodies, frame, view)
            shown += 1  # (on the screen before Closed can say the window went)
            window.show(image, i / fps)
    except Closed:
        pass
    finally:
        window.close()
    return shown
