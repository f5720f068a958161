"""`max2code sim SCENE --until T`: run a scene in the predictive engine.

    max2code sim examples/scenes/pile.toml --until 5 --gif pile.gif --events pile.jsonl
    max2code sim SCENE [--until T] [--fps F] [--gif FILE | --mp4 FILE | --png-dir DIR | --svg FILE]
                       [--size WxH] [--events FILE] [--live] [--json]

Frames show the exact state at each frame time (1/fps apart, from 0 to T); the physics runs
from event to event regardless. The event log has one JSON object per line: time, kind, the two
bodies' names, the normal (from a to b), the contact point, the closing speed and the impulse;
the same scene gives the same log, byte for byte. Exit status 0, or 1 with
`file:line:col: error: ...` for a bad scene and `file: error: ...` when the engine stops.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time

from ..jsonsafe import json_safe
from ..output import write_if_changed


# Frames a run with pictures may ask for: every frame is kept until the end (the view is fit to
# every body in every frame), about 13 kB each for examples/scenes/pile.toml's 66 bodies.
MAX_FRAMES = 100_000
# The slowest frame rate pictures are made at (--fps 1e-300 overflowed the GIF's delay field).
MIN_PICTURE_FPS = 0.01


class _Counter:
    """Stands in for the event list when no log is written: counts what goes by."""

    def __init__(self) -> None:
        self.n = 0

    def extend(self, events) -> None:
        for _ in events:
            self.n += 1

    def __len__(self) -> int:
        return self.n


def event_record(world, ev) -> dict:
    names = [b.name for b in world.bodies]
    rec: dict = {"t": ev.time, "kind": ev.kind}
    if ev.kind == "timer":
        rec["timer"] = ev.a
        return rec
    rec["a"] = names[ev.a]
    rec["b"] = names[ev.b] if ev.b >= 0 else None
    if ev.kind == "collision":
        rec.update(normal=list(ev.normal), point=list(ev.point), speed=ev.speed, impulse=ev.impulse)
    return rec


def event_log(world, events) -> str:
    return "".join(json.dumps(json_safe(event_record(world, e)), separators=(",", ":"),
                              allow_nan=False) + "\n" for e in events)


def _size(text: str) -> tuple[int, int]:
    try:
        w, h = text.lower().split("x")
        return int(w), int(h)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT, like 640x480, not {text!r}") from None


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(prog="max2code sim", description=__doc__.split("\n\n")[0])
    ap.add_argument("scene", metavar="SCENE", help="a scene file (.toml or .json)")
    ap.add_argument("--until", type=float, metavar="T",
                    help="simulated seconds (default: the scene's 'until', else 10)")
    ap.add_argument("--fps", type=float, metavar="F", help="frames per second (default: the scene's, else 30)")
    out = ap.add_mutually_exclusive_group()
    out.add_argument("--gif", metavar="FILE", help="an animated GIF of the frames")
    out.add_argument("--mp4", metavar="FILE", help="an MP4 video of the frames")
    out.add_argument("--png-dir", metavar="DIR", help="one PNG per frame in DIR")
    out.add_argument("--svg", metavar="FILE", help="an SVG of the last frame")
    out.add_argument("--png", metavar="FILE", help="a PNG of the last frame")
    ap.add_argument("--size", type=_size, default=(640, 480), metavar="WxH", help="picture size in pixels")
    ap.add_argument("--events", metavar="FILE", help="write the event log (JSON lines)")
    ap.add_argument("--live", action="store_true", help="show the run in a window (needs pygame)")
    ap.add_argument("--json", action="store_true", help="print the summary as JSON")
    args = ap.parse_args(argv)

    from ..engine.scenefile import SceneError, build_world, load
    from ..engine.world import EngineError

    try:
        scene = load(args.scene)
    except SceneError as exc:
        for d in exc.diagnostics:
            print(d, file=sys.stderr)
        return 1
    until = args.until if args.until is not None else (scene.until or 10.0)
    fps = args.fps if args.fps is not None else (scene.fps or 30.0)
    if not (0 <= until < math.inf and 0 < fps < math.inf):
        print("max2code sim: error: --until must be finite and >= 0, --fps finite and > 0",
              file=sys.stderr)
        return 1
    pictures = args.gif or args.mp4 or args.png_dir or args.svg or args.png or args.live
    if pictures and fps < MIN_PICTURE_FPS:
        print(f"max2code sim: error: --fps {fps:g} is below {MIN_PICTURE_FPS:g} for pictures (a "
              "frame every 100 s at most: a GIF holds a frame's delay up to 655 s)", file=sys.stderr)
        return 1
    if pictures and until * fps + 1 > MAX_FRAMES:
        print(f"max2code sim: error: --until {until:g} at --fps {fps:g} asks for "
              f"{until * fps + 1:.0f} frames; at most {MAX_FRAMES} (each is kept, to fit the "
              "view to every body in every frame): a lower --fps, or no picture", file=sys.stderr)
        return 1
    try:
        world = build_world(scene)
        e0 = world.energy(0.0)
        # the events are kept only for the log: without --events they are counted as they
        # stream by (a 1000-disc gas for 300 s kept 373 MB of them)
        log: list | _Counter = [] if args.events else _Counter()
        start = time.perf_counter()
        if pictures:
            from ..engine.frames import render_bodies, run_frames
            # (--png and --svg draw the state at T itself, a frame of its own when T is not
            # a frame time)
            frames = list(run_frames(world, until, fps, log, end_frame=bool(args.png or args.svg)))
        else:
            log.extend(world.stream_to(until))
        seconds = time.perf_counter() - start
        e1 = world.energy(until)
    except SceneError as exc:  # a body the engine refused, at its place in the file
        for d in exc.diagnostics:
            print(d, file=sys.stderr)
        return 1
    except EngineError as exc:
        print(f"{args.scene}: error: engine: {exc}", file=sys.stderr)
        return 1
    # the pictures first: a run that fails there leaves every output as it was, the event log
    # included
    if pictures:
        rc = _pictures(args, scene, world, frames, fps)
        if rc:
            return rc
    if args.events:
        write_if_changed(args.events, event_log(world, log))
    stats = world.stats()
    summary = {"scene": scene.name, "until": until, "bodies": len(world.bodies),
               "events": stats["events"], "collisions": stats["collisions"],
               "reported": len(log), "wall_seconds": seconds,
               "energy_start": e0, "energy_end": e1,
               "energy_drift": (e1 - e0) / abs(e0) if e0 else e1 - e0,
               "stats": stats}
    if args.json:
        print(json.dumps(json_safe(summary), indent=1, allow_nan=False))
    else:
        print(f"{scene.name}: {len(world.bodies)} bodies, {until:g} s simulated in {seconds:.3f} s: "
              f"{stats['collisions']} collisions, {stats['events']} events "
              f"({stats['cell_crossings']} cell crossings, {stats['windows']} windows); "
              f"energy {e0:.9g} -> {e1:.9g}")
    return 0


def picture_view(scene, bodies, frames, width: int, height: int):
    """The scene's view, else the smallest one holding every body in every frame (bodies that
    travel stay in the picture: fitting the first frame only would lose them)."""
    from ..render.fit import fit_view
    from ..render.model import View

    if scene.view:
        return View(*scene.view, width=width, height=height)
    return fit_view(bodies, frames, width, height)


def _pictures(args, scene, world, frames, fps: float) -> int:
    """Write the pictures asked for; 0, or 1 after an `error:` line (a writer's failure leaves
    no partial file: every writer renames a finished temporary file into place)."""
    from ..diagnostics import Max2CodeError
    from ..engine.frames import render_bodies
    from ..render.model import RenderModelError

    try:
        from ..render import write
    except ImportError as exc:
        print(f"max2code sim: error: pictures are not available ({exc})", file=sys.stderr)
        return 1
    bodies = render_bodies(world)
    width, height = args.size
    try:
        view = picture_view(scene, bodies, frames, width, height)
        if args.gif:
            write.write_gif(args.gif, bodies, frames, view, fps)
        elif args.mp4:
            write.write_mp4(args.mp4, bodies, frames, view, fps)
        elif args.png_dir:
            write.write_png_dir(args.png_dir, bodies, frames, view)
        elif args.svg:
            write.write_svg(args.svg, bodies, frames[-1], view)
        elif args.png:
            write.write_png(args.png, bodies, frames[-1], view)
    except Max2CodeError as exc:
        for d in exc.diagnostics:
            print(d, file=sys.stderr)
        return 1
    except OSError as exc:
        name = getattr(exc, "filename", None) or "max2code sim"
        print(f"{name}: error: cannot write output: {exc.strerror or exc}", file=sys.stderr)
        return 1
    except (RenderModelError, write.RenderUnavailable) as exc:
        print(f"max2code sim: error: {exc}", file=sys.stderr)
        return 1
    if args.live:
        _live(bodies, frames, view, fps)
    return 0


def _live(bodies, frames, view, fps: float) -> None:
    """The window is a convenience: without pygame (or a display) say so and go on."""
    from ..render import live
    from ..render.write import RenderUnavailable

    try:
        live.show(bodies, frames, view, fps)
    except RenderUnavailable as exc:
        print(f"max2code sim: note: no live window: {exc}; the run went on without it",
              file=sys.stderr)
