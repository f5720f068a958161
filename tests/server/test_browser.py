"""The page in a real browser: Debian's Chromium (/usr/bin/chromium) driven by Playwright.
It loads, joins, plays scripted keys, and a pixel probe of its canvas finds each player where
the server's world says it is at the frame's time; two browsers share one world."""

from __future__ import annotations

import io
import math
import os
import shutil

import pytest

from conftest import require_module
from .conftest import ARENA, start

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


@pytest.fixture
def server():
    running = start(ARENA)
    yield running
    running.stop()


def open_page(browser, server):
    # (bypass_csp: Playwright evaluates the tests' expressions as strings, which the page's
    # Content-Security-Policy rightly forbids)
    page = browser.new_page(viewport={"width": 900, "height": 760}, bypass_csp=True)
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto(f"http://127.0.0.1:{server.port}/")
    page.wait_for_function("window.m2c && m2c.state.joined && m2c.state.rtt !== null", timeout=30000)
    return page, errors


def probe(page, server, bodies):
    """Freeze every page's drawing at one server time T (all messages up to T received), and
    return, per body, the canvas pixel where the server's world puts the body at T and that
    pixel's colour in the page's canvas."""
    def now():
        room = server.server.rooms["main"]
        room.advance(room.clock())
        t = room.world.time
        return t, room.seq, {b: room.world.pose(b, t) for b in bodies}
    t, seq, poses = server.call(now)
    page.wait_for_function(f"m2c.state.n >= {seq}", timeout=10000)
    page.evaluate(f"m2c.freeze({t!r})")
    from PIL import Image
    image = Image.open(io.BytesIO(page.locator("#view").screenshot())).convert("RGB")
    out = {}
    for b, (x, y, a) in poses.items():
        # half a radius behind the centre, away from the spoke (drawn from the centre along
        # the body's angle): a pixel only the body's fill covers
        r = page.evaluate(f"m2c.state.bodies[{b}].shape.r") / 2
        px, py = page.evaluate(f"m2c.toPixel({x - r * math.cos(a)!r}, {y - r * math.sin(a)!r})")
        out[b] = ((px, py), image.getpixel((int(px), int(py))), image)
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
    (px, py), colour, image = found[4]
    image.save(tmp_path / "probe.png")
    assert colour == hex_rgb("#c44e52"), (t, px, py, colour)
    # the player left its start: the start pixel is no longer red
    sx, sy = page.evaluate("m2c.toPixel(-1.0, 0.0)")
    assert image.getpixel((int(sx), int(sy))) != hex_rgb("#c44e52")
    # the keys reached the server as input events for player1, and nothing was refused
    inputs = server.call(lambda: server.server.rooms["main"].stats.inputs)
    assert inputs >= 4
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
    pos = server.call(lambda: {k: server.server.rooms["main"].world.pose(k) for k in (4, 5)})
    assert pos[4][1] < -0.05 and pos[5][0] < 0.95
    assert errors_a == errors_b == []
