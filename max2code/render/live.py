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


def show(bodies: Sequence[Body], frames: Iterable[Frame], view: View, fps: float = 60.0,
         title: str = "max2code sim", clock: Callable[[], float] = time.monotonic,
         sleep: Callable[[float], None] = time.sleep) -> int:
    """Show frames in a window, frame i at i / fps seconds of wall time after the first (late
    frames are shown at once, never skipped, so the picture is right even when drawing is slow).
    Returns the number of frames shown: fewer than given when the window was closed."""
    pygame = _pygame()
    if pygame is None:
        raise RenderUnavailable("the live window needs pygame: pip install 'max2code[live]'")
    raster, _ = drawing_modules()
    fps = check_fps(fps)
    try:
        pygame.display.init()
        driver = pygame.display.get_driver()
        if driver in HEADLESS and not os.environ.get("SDL_VIDEODRIVER"):
            # SDL fell back to drawing nowhere (no display): say so, rather than spend the
            # run's wall time on a window nobody sees (a driver the user chose is obeyed)
            raise pygame.error(f"no display (SDL's video driver fell back to '{driver}')")
        screen = pygame.display.set_mode((view.width, view.height))
    except pygame.error as exc:  # no display to open a window on
        pygame.display.quit()
        raise RenderUnavailable(f"pygame cannot open a window: {exc}") from None
    try:
        pygame.display.set_caption(title)
        start = clock()
        shown = 0
        for i, frame in enumerate(frames):
            image = raster.frame_image(bodies, frame, view)
            surface = pygame.image.frombuffer(image.tobytes(), image.size, "RGB")
            wait = start + i / fps - clock()
            if wait > 0:
                sleep(wait)
            screen.blit(surface, (0, 0))
            pygame.display.flip()
            shown += 1
            for event in pygame.event.get():
                if event.type == pygame.QUIT or (event.type == pygame.KEYDOWN
                                                 and event.key == pygame.K_ESCAPE):
                    return shown
        return shown
    finally:
        pygame.display.quit()
