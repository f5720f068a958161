"""The page in a real browser: Debian's Chromium (/usr/bin/chromium) driven by Playwright.
It loads, joins, plays scripted keys, and a pixel probe of its canvas finds each player where
the server's world says it is at the frame's time; two browsers share one world."""

from __future__ import annotations

import asyncio
import io
import math
import os
import re
import subprocess
import sys
import threading
import time

import pytest

from conftest import require_module
from .client import Client
from .conftest import ARENA

CHROMIUM = "/usr/bin/chromium"


@pytest.fixture(scope="module")
def browser():
    if not os.path.exists(CHROMIUM):
        message = f"{CHROMIUM} is not installed (apt-get install chromium; scripts/setup does)"
        if os.environ.get("CI"):
            pytest.fail(message + " -- required in CI")
        pytest.skip(message)
    sync_api = require_module("playwright.sync_api")
    with sync_api.sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=["--no-sandbox"])
        yield b
        b.close()


class Served:
    """`max2code serve` in a process of its own (as a player starts it), and a protocol client
    (tests/server/client.py) in the same room: what the server says, message by message."""

    def __init__(self, path=ARENA, watch: bool = True) -> None:
        self.process = subprocess.Popen(
            [sys.executable, "-m", "max2code", "serve", str(path), "--port", "0"],
            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        line = self.process.stderr.readline()
        m = re.search(r"http://127\.0\.0\.1:(\d+)/", line)
        assert m, line
        self.port = int(m.group(1))
        self.watcher: Client | None = None
        self.done = threading.Event()
        self.thread = None
        if watch:
            self.watch()

    def watch(self) -> None:
        """Join the watcher (at once, or later: a room's world starts at its first join)."""
        self.failure: BaseException | None = None
        self.thread = threading.Thread(target=self._main, daemon=True)
        self.thread.start()
        for _ in range(600):
            if self.watcher is not None or self.failure is not None:
                break
            time.sleep(0.1)
        assert self.watcher is not None, f"the watcher did not join: {self.failure!r}"

    def _main(self) -> None:
        try:
            asyncio.run(self._watch())
        except BaseException as exc:   # (reported by the test's assertion)
            self.failure = exc

    async def _watch(self) -> None:
        # (a thread and loop of its own: Playwright's synchronous API owns the main thread's)
        self.watcher = await Client.join(f"ws://127.0.0.1:{self.port}/ws", play=False)
        while not self.done.is_set():
            await self.watcher.receive(0.05)
        await self.watcher.ws.close()

    def catch_up(self, n: int) -> None:
        """Wait until the watcher has message n."""
        for _ in range(300):
            if self.watcher.n >= n:
                return
            time.sleep(0.02)

    def stop(self) -> None:
        self.done.set()
        if self.thread is not None:
            self.thread.join(30)
        self.process.terminate()
        self.process.wait(30)


@pytest.fixture
def server():
    served = Served()
    yield served
    served.stop()


def open_page(browser, server):
    # (bypass_csp: Playwright evaluates the tests' expressions as strings, which the page's
    # Content-Security-Policy rightly forbids)
    page = browser.new_page(viewport={"width": 900, "height": 760}, bypass_csp=True)
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto(f"http://127.0.0.1:{server.port}/")
    page.wait_for_function("window.m2c && m2c.state.joined && m2c.state.rtt !== null", timeout=30000)
    return page, errors


def probe(page, server, bodies, ahead: float = 0.0):
    """Freeze the page's drawing at its server time T (`ahead` seconds after now), once it and
    the watcher hold the same messages, and return per body: the canvas pixel where the
    server's segments put the body at T, and that pixel's colour in the page's canvas."""
    # (frozen and n read in one turn of the page's loop: a message between two evaluates
    # left the drawn frame older than the n it was compared at)
    t, n = page.evaluate(f"(() => [m2c.freeze(m2c.serverNow() + {ahead!r}), m2c.state.n])()")
    server.catch_up(n)
    # (the world goes on: the watcher may already hold a later message than the page did)
    assert server.watcher.n >= n
    from PIL import Image
    image = Image.open(io.BytesIO(page.locator("#view").screenshot())).convert("RGB")
    out = {}
    for b in bodies:
        x, y, a = server.watcher.pose(b, t, n)
        # half a radius behind the centre, away from the spoke (drawn from the centre along
        # the body's angle): a pixel only the body's fill covers
        r = page.evaluate(f"m2c.state.bodies[{b}].shape.r") / 2
        px, py = page.evaluate(f"m2c.toPixel({x - r * math.cos(a)!r}, {y - r * math.sin(a)!r})")
        on = 0 <= px < image.width and 0 <= py < image.height    # (None: off the canvas)
        out[b] = ((px, py), image.getpixel((int(px), int(py))) if on else None, image, (x, y))
    page.evaluate("m2c.thaw()")
    return t, out


def hex_rgb(colour: str) -> tuple[int, int, int]:
    return tuple(int(colour[k:k + 2], 16) for k in (1, 3, 5))


def test_page_joins_plays_and_draws_where_the_server_says(browser, server, tmp_path):
    page, errors = open_page(browser, server)
    state = page.evaluate("m2c.state.you")
    assert state == [4]
    text = page.locator("#status").inner_text()
    assert "round trip" in text and "player1" in text
    page.locator("#view").click(position={"x": 5, "y": 5})   # focus, and a pointer input
    page.wait_for_timeout(200)
    page.keyboard.down("ArrowRight")
    page.wait_for_timeout(400)
    page.keyboard.down("ArrowUp")
    page.wait_for_timeout(300)
    page.keyboard.up("ArrowRight")
    page.keyboard.up("ArrowUp")
    page.wait_for_timeout(200)
    t, found = probe(page, server, [4])
    (px, py), colour, image, _ = found[4]
    image.save(tmp_path / "probe.png")
    assert colour == hex_rgb("#c44e52"), (t, px, py, colour)
    # the player left its start: the start pixel is no longer red
    sx, sy = page.evaluate("m2c.toPixel(-1.0, 0.0)")
    assert image.getpixel((int(sx), int(sy))) != hex_rgb("#c44e52")
    # the keys reached the server as input events for player1, and nothing was refused
    inputs = [e for m in server.watcher.messages if m["type"] == "ev" for e in m["ev"] if e[0] == 5]
    assert len(inputs) >= 4 and {e[1] for e in inputs} == {4}
    assert page.evaluate("m2c.state.refused") == [] and errors == []
    assert page.evaluate("m2c.state.closed") is None


def test_two_browsers_share_one_world(browser, server):
    a, errors_a = open_page(browser, server)
    b, errors_b = open_page(browser, server)
    assert a.evaluate("m2c.state.you") == [4] and b.evaluate("m2c.state.you") == [5]
    a.keyboard.down("ArrowDown")
    b.keyboard.down("ArrowLeft")
    b.wait_for_timeout(500)
    a.keyboard.up("ArrowDown")
    b.keyboard.up("ArrowLeft")
    for page in (a, b):
        t, found = probe(page, server, [4, 5])
        assert found[4][1] == hex_rgb("#c44e52"), (t, found[4][:2])
        assert found[5][1] == hex_rgb("#4c72b0"), (t, found[5][:2])
    # player2 went left, player1 down: both moved in both pages' world
    assert found[4][3][1] < -0.05 and found[5][3][0] < 0.95
    assert errors_a == errors_b == []


BOUNCERS = """name = "bouncers"
gravity = [0.0, -9.81]
view = [-0.5, -0.2, 4.5, 3.0]

[[bodies]]
name = "floor"
kind = "static"
shape = "segment"
points = [[-0.5, 0], [4.5, 0]]
restitution = 1.0
""" + "".join(f"""
[[bodies]]
name = "ball{k}"
shape = "circle"
position = [{0.8 * k}, {1.0 + 0.35 * k}]
radius = 0.15
restitution = 1.0
""" for k in range(5))


def test_page_draws_falling_bodies_where_the_server_says(browser, tmp_path):
    """Five balls bouncing for ever under gravity: their segments travel in protocol 4's
    `fall` list (acceleration left off), and the page gives them the world's g back. Its poses
    0.25 s past its last message (where g's part, g s^2 / 2, is 0.31 m, twice a ball's radius)
    are the server's; and each ball's fill is drawn where the server's segments put it."""
    scene = tmp_path / "bouncers.toml"
    scene.write_text(BOUNCERS)
    served = Served(scene)
    try:
        page, errors = open_page(browser, served)
        assert page.evaluate("m2c.state.g") == [0, -9.81]
        page.wait_for_timeout(300)
        balls = page.evaluate("""Object.values(m2c.state.bodies)
            .filter((b) => b.kind === 'dynamic').map((b) => [b.id, b.fill])""")
        assert len(balls) == 5
        ids = [i for i, _ in balls]
        n, t, poses = page.evaluate(f"""(() => {{ const t = m2c.serverNow() + 0.25;
            return [m2c.state.n, t, {ids}.map((id) => m2c.poseAt(id, t))]; }})()""")
        served.catch_up(n)
        held = served.watcher.history[n]
        assert sum(len(seg) == 9 and seg[7:] == [0, -9.81] for seg, _ in held.values()) == 5
        for i, pose in zip(ids, poses):
            assert pose == pytest.approx(served.watcher.pose(i, t, n), abs=1e-9), i
        falls = sum(len(m.get("fall", [])) for m in served.watcher.messages if m["type"] == "ev")
        assert falls > 0 and all(m.get("seg", []) == [] for m in served.watcher.messages
                                 if m["type"] == "ev")
        t, found = probe(page, served, ids)
        wrong = [(i, found[i][1], fill) for i, fill in balls if found[i][1] != hex_rgb(fill)]
        assert not wrong, (t, wrong)
        assert errors == []
    finally:
        served.stop()


BREAKOUT = "/work/shared/corpus/pge-python/examples/breakout-breakout.py"


@pytest.mark.skipif(not os.path.exists(BREAKOUT), reason="no PGE corpus here")
def test_page_stops_drawing_removed_bricks(browser):
    """PGE's breakout served (`max2code serve GAME.py`): once the ball has knocked bricks out,
    the page draws the bricks still there and nothing where the removed ones were."""
    served = Served(BREAKOUT, watch=False)
    try:
        page, errors = open_page(browser, served)
        # (in one evaluation: the game runs on meanwhile, knocking bricks out)
        start = page.evaluate("""Object.values(m2c.state.bodies).map((b) => [b.id, b.name, b.fill,
            m2c.toPixel(...m2c.poseAt(b.id, m2c.serverNow()).slice(0, 2))])""")
        ids = [i for i, *_ in start]
        bricks = [i for i, name, _, _ in start if name.startswith("box-") and i >= 4]
        centres = {i: c for i, _, _, c in start}
        fill = hex_rgb(next(f for i, _, f, _ in start if i in bricks))
        page.wait_for_function(f"Object.keys(m2c.state.bodies).length <= {len(ids) - 4}", timeout=20000)
        # the frozen frame, the bodies it drew and where it drew the ball, in one evaluation:
        # messages go on arriving after the freeze (a brick removed then is still drawn)
        t, live, balls = page.evaluate("""(() => {
            const t = m2c.freeze(m2c.serverNow());
            const bodies = Object.values(m2c.state.bodies);
            return [t, bodies.map((b) => b.id),
                    bodies.filter((b) => b.kind === "dynamic").map((b) => [
                        ...m2c.toPixel(...m2c.poseAt(b.id, t).slice(0, 2)),
                        b.shape.r * (m2c.toPixel(1, 0)[0] - m2c.toPixel(0, 0)[0]) + 8])];
        })()""")
        live = set(live)
        # (a brick under the ball is not probed)

        def covered(c) -> bool:
            return any(math.hypot(c[0] - x, c[1] - y) < r for x, y, r in balls)
        from PIL import Image
        image = Image.open(io.BytesIO(page.locator("#view").screenshot())).convert("RGB")
        gone = [i for i in bricks if i not in live]
        kept = [i for i in bricks if i in live]
        assert len(gone) >= 4 and kept
        for i in kept:
            if not covered(centres[i]):
                assert image.getpixel(tuple(int(v) for v in centres[i])) == fill, (i, t, balls)
        for i in gone:
            assert image.getpixel(tuple(int(v) for v in centres[i])) != fill, (i, t, balls)
        assert errors == []
    finally:
        served.stop()


def test_page_draws_compound_bodies(browser):
    """examples/scenes/compound.toml: every compound reaches the page with its parts (the post
    2, the dumbbell 3, the L 2), and the dumbbell's bar is drawn, in its fill, at the centre of
    mass where the server's segments put it (a point only the bar covers)."""
    from conftest import ROOT

    served = Served(ROOT / "examples" / "scenes" / "compound.toml")
    try:
        page, errors = open_page(browser, served)
        page.wait_for_timeout(300)
        shapes = page.evaluate("""Object.values(m2c.state.bodies).filter((b) => b.shape.parts)
            .map((b) => [b.name, b.fill, b.shape.parts.length])""")
        assert sorted((name, n) for name, _, n in shapes) == [("L", 2), ("dumbbell", 3), ("post", 2)]
        (i, fill), = page.evaluate("""Object.values(m2c.state.bodies)
            .filter((b) => b.name === 'dumbbell').map((b) => [b.id, b.fill])""")
        t, n = page.evaluate("(() => [m2c.freeze(m2c.serverNow()), m2c.state.n])()")
        served.catch_up(n)
        from PIL import Image
        image = Image.open(io.BytesIO(page.locator("#view").screenshot())).convert("RGB")
        x, y, _ = served.watcher.pose(i, t, n)
        px, py = page.evaluate(f"m2c.toPixel({x!r}, {y!r})")
        assert image.getpixel((int(px), int(py))) == hex_rgb(fill), (t, x, y)
        page.evaluate("m2c.thaw()")
        assert errors == []
    finally:
        served.stop()


TIPPERS = """name = "tippers"
gravity = [0.0, -1.0]
view = [-0.5, -0.1, 5.0, 3.0]

[engine]
contact_step = 0.004166666666666667

[[bodies]]
name = "floor"
kind = "static"
shape = "segment"
points = [[-0.5, 0], [5.0, 0]]
friction = 0.5
""" + "".join(f"""
[[bodies]]
name = "box{k}"
shape = "box"
size = [0.5, 0.5]
position = [{0.9 * k}, {0.36 + 0.4 * k}]
angle = 0.6
restitution = 0.0
friction = 0.5
color = "#d0602a"
""" for k in range(6))


def test_page_draws_held_quadratics_where_the_server_says(browser, tmp_path):
    """Six boxes (the tipping-box scene's, under g = 1 m/s^2 so that each tips for some 1.5 s)
    dropped one after another onto a corner: while the solver holds one tipping, its smooth
    history gets it a quadratic (protocol version 5: angle + omega s + alpha s^2/2; or a cubic,
    the next test's). Once the page holds a quadratic, its pose 0.2 s on (where alpha's term, alpha s^2/2, is at least 1e-3 rad)
    is the server's (the watcher's, tests/server/client.py); and the box's fill is drawn there."""
    scene = tmp_path / "tippers.toml"
    scene.write_text(TIPPERS)
    served = Served(scene, watch=False)
    try:
        page, errors = open_page(browser, served)   # (the world starts at the page's join, the
        served.watch()                              # boxes tip from 0 to some 4 s)
        first = served.watcher.n
        # (found, frozen 0.2 s on and evaluated in one turn of the page's loop: no message
        # between them)
        found = page.wait_for_function(f"""(() => {{ if (m2c.state.n <= {first}) return null;
            for (const [id, g] of Object.entries(m2c.state.segs))
                if (Math.abs(g.v[8]) > 0.05 && !g.v[9] && !g.v[10] && !g.v[11]) {{  // (no jerk)
                    const t = m2c.freeze(g.t + 0.2);
                    return [Number(id), t, m2c.poseAt(Number(id), t), g.v[8], m2c.state.n];
                }}
            return null; }})()""", polling=5, timeout=30000).json_value()
        i, t, pose, alpha, n = found
        served.catch_up(n)
        assert len(served.watcher.history[n][i][0]) == 10
        assert pose == pytest.approx(served.watcher.pose(i, t, n), abs=1e-9)
        assert abs(alpha) * 0.2 ** 2 / 2 >= 1e-3
        from PIL import Image
        image = Image.open(io.BytesIO(page.locator("#view").screenshot())).convert("RGB")
        px, py = page.evaluate(f"m2c.toPixel({pose[0]!r}, {pose[1]!r})")
        assert image.getpixel((int(px), int(py))) == hex_rgb("#d0602a"), (t, pose)
        page.evaluate("m2c.thaw()")
        assert errors == []
    finally:
        served.stop()


def test_page_draws_held_cubics_where_the_server_says(browser, tmp_path):
    """The same tipping boxes: a box whose recent history is smooth gets a cubic (protocol
    version 6: + (jx, jy) s^3/6 and ja s^3/6 for the angle). Once the page holds one whose
    angular jerk moves the angle by at least 2e-4 rad 0.2 s on, the page's pose there is the
    server's evaluation (wire.pose, through the watcher) to 1e-9: a sign or a factor (s^3/2
    for s^3/6) wrong in client.js's jerk terms moves it by some 1e-4."""
    scene = tmp_path / "tippers.toml"
    scene.write_text(TIPPERS)
    served = Served(scene, watch=False)
    try:
        page, errors = open_page(browser, served)
        served.watch()
        first = served.watcher.n
        found = page.wait_for_function(f"""(() => {{ if (m2c.state.n <= {first}) return null;
            for (const [id, g] of Object.entries(m2c.state.segs))
                if (Math.abs(g.v[11]) * 0.2 ** 3 / 6 >= 2e-4) {{
                    const t = m2c.freeze(g.t + 0.2);
                    return [Number(id), t, m2c.poseAt(Number(id), t), g.v.slice(9), m2c.state.n];
                }}
            return null; }})()""", polling=5, timeout=30000).json_value()
        i, t, pose, jerks, n = found
        served.catch_up(n)
        seg = served.watcher.history[n][i][0]
        assert len(seg) == 13 and seg[10:] == jerks
        assert pose == pytest.approx(served.watcher.pose(i, t, n), abs=1e-9)
        page.evaluate("m2c.thaw()")
        assert errors == []
    finally:
        served.stop()
