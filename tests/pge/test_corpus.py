"""PGE's own example games (../shared/corpus/pge-python/examples, real programs nobody here wrote)
run unmodified under `max2code pge --headless`, and play as their authors meant."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from .conftest import CORPUS, pge_run

pytestmark = pytest.mark.skipif(not CORPUS.is_dir(), reason=f"no PGE corpus at {CORPUS}")


def game(name: str) -> str:
    return str(CORPUS / "examples" / f"{name}.py")


def test_breakout_every_brick_hit_vanishes_and_the_game_ends_as_it_must(tmp_path: Path) -> None:
    """Breakout's triangles multiply the ball's velocity by 1.15 at every hit (push_it), and
    the faster the ball the sooner its next hit: its speed can run away in finite time (the
    sum of the times between hits converges). Which comes first, the last brick or the
    runaway, is chaotic: any change to the engine's arithmetic can flip it (8a5a77c did: the
    ball now runs away at t = 2.84 s). Either way the bricks vanish at the instant they are
    hit and are never hit again; a win exits 0 4/6 s after the last brick; a runaway ends in
    the engine's named error at the program's pge.run line, after the triangle hits' speeds
    grew by orders of magnitude (checked on the run up to just before it)."""
    r, log = pge_run(tmp_path, game("breakout-breakout"))
    won = r.returncode == 0
    if not won:   # the runaway: named, located, and the run before it shows why
        assert r.returncode == 1 and "breakout-breakout.py:156:5: error:" in r.stderr, r.stderr
        assert "stuck" in r.stderr and "too fast for double precision" in r.stderr, r.stderr
        t_stop = float(r.stderr.split("of t = ")[1].split()[0])
        r, log = pge_run(tmp_path, game("breakout-breakout"), "--until", f"{t_stop - 0.01}")
        assert r.returncode == 0, r.stderr
        tri = [e["speed"] for e in log
               if e["kind"] == "collision" and "poly3" in e["a"] + e["b"]]
        assert max(tri[-3:]) > 100 * max(tri[:3]), tri
    removed = [e for e in log if e["kind"] == "rm"]
    # the bricks (made after the 4 borders: box-4 .. box-30), each at most once
    assert removed and len({e["object"] for e in removed}) == len(removed)
    assert {e["object"] for e in removed} <= {f"box-{i}" for i in range(4, 31)}
    hits = {(e["t"], e["b"]) for e in log if e["kind"] == "collision"}
    for e in removed:  # removed at the instant the ball hit it, by its on_collision callback
        assert (e["t"], e["object"]) in hits
    # a removed brick is never hit again
    gone = {e["object"]: e["t"] for e in removed}
    assert not [e for e in log if e["kind"] == "collision" and e["b"] in gone and e["t"] > gone[e["b"]]]
    if won:   # all 27 gone; finish_game runs 4 s / slow_down 6 after the last, and exits 0
        assert len(removed) == 27
        assert r.stderr.split("simulated")[0].endswith(f"{removed[-1]['t'] + 4 / 6:g} s ")


def test_snooker_triangles_speed_the_ball_up_and_it_stays_on_the_table(tmp_path: Path) -> None:
    r, log = pge_run(tmp_path, game("snooker-snooker"), "--until", "3")
    assert r.returncode == 0, r.stderr
    hits = [e for e in log if e["kind"] == "collision"]
    assert {e["a"] for e in hits} | {e["b"] for e in hits} >= {"circle-6", "poly3-0", "poly3-1"}
    for e in hits:  # the cushions hold the ball: every contact inside the table
        assert 0.0 <= e["point"][0] <= 1.0 and 0.0 <= e["point"][1] <= 1.0
    # push_it multiplies the ball's velocity by 1.15 at each triangle hit: the ball, elastic
    # otherwise, gets faster (closing speeds at the cushions grow)
    cushions = [e["speed"] for e in hits if e["b"].startswith("box") or e["a"].startswith("box")]
    assert max(cushions[-5:]) > 1.5 * max(cushions[:3])
    # the game's pockets (box_of) are never placed by its main(): nothing is potted
    assert not [e for e in log if e["kind"] == "rm"]


def test_snooker_a_mouse_click_changes_the_game_from_its_time_on(tmp_path: Path) -> None:
    script = tmp_path / "click.jsonl"
    script.write_text('{"t": 0.5, "type": "MOUSEBUTTONDOWN", "pos": [100, 700], "button": 1}\n')
    _, quiet = pge_run(tmp_path, game("snooker-snooker"), "--until", "2")
    r, clicked = pge_run(tmp_path, game("snooker-snooker"), "--until", "2", "--input", str(script))
    assert r.returncode == 0, r.stderr
    before = lambda log: [e for e in log if e["t"] < 0.5 and e["kind"] == "collision"]  # noqa: E731
    after = lambda log: [e for e in log if e["t"] > 0.5 and e["kind"] == "collision"]  # noqa: E731
    assert before(quiet) == before(clicked)
    assert after(quiet)[0] != after(clicked)[0]
    assert {"t": 0.5, "kind": "input", "type": "MOUSEBUTTONDOWN", "pos": [100, 700],
            "button": 1} in clicked


def test_bagatelle_launched_balls_drop_out_at_the_bottom(tmp_path: Path) -> None:
    script = tmp_path / "launch.jsonl"
    script.write_text("".join(json.dumps({"t": t, "type": "MOUSEBUTTONDOWN", "pos": [x, 80],
                                          "button": 1}) + "\n"
                              for t, x in ((0.1, 400), (1.5, 420), (3.0, 380))))
    r, log = pge_run(tmp_path, game("bagatelle-bagatelle"), "--input", str(script))
    assert r.returncode == 0, r.stderr
    # each click puts a ball in the shoot (mouse_press) ...
    made = sorted({n for e in log if e["kind"] == "collision" for n in (e["a"], e["b"])
                   if n.startswith("circle") and int(n.split("-")[1]) >= 15})
    assert len(made) == 3
    # ... which hits things on its way and is removed when it reaches the bottom border
    # (box-12, the south side: delete_ball), at the instant it touches it
    removed = [e for e in log if e["kind"] == "rm"]
    assert [e["object"] for e in removed] == made
    for e in removed:
        assert any(c["kind"] == "collision" and c["t"] == e["t"] and "box-12" in (c["a"], c["b"])
                   and e["object"] in (c["a"], c["b"]) for c in log)


def test_rotation_the_box_lands_on_a_corner_and_tips_over(tmp_path: Path) -> None:
    r, log = pge_run(tmp_path, game("rotation-rotation"))
    assert r.returncode == 0, r.stderr
    hits = [e for e in log if e["kind"] == "collision"]
    # the falling box (box-5) lands with its lower left corner (x 0.47) on the top of the fixed
    # red box (y 0.4), its centre beyond the red box's edge (0.49), so it turns off it to the
    # floor (box-1)
    assert (hits[0]["a"], hits[0]["b"]) in (("box-0", "box-5"), ("box-5", "box-0"))
    assert hits[0]["point"] == pytest.approx([0.47, 0.4], abs=1e-9)
    assert any("box-1" in (e["a"], e["b"]) for e in hits)
    assert r.stderr.split(": ")[2].startswith("2.5 s simulated")


def test_springs_simple_oscillates_as_a_damped_spring_and_settles_at_its_rest_length(
        tmp_path: Path) -> None:
    # a 1 kg ball hangs 0.6 below a fixed one on a spring k = 100, d = 3, rest length 0.5 (no
    # gravity): a linear damped oscillator of amplitude 0.1 about the midline y = 0.45
    r, log = pge_run(tmp_path, game("springs-simple"), "--until", "3")
    assert r.returncode == 0, r.stderr
    events = [e for e in log if e["kind"] == "spring"]
    omega_d = math.sqrt(100 - 1.5 ** 2)
    ends = [e["t"] for e in events if e["what"] == "end"]
    mids = [e["t"] for e in events if e["what"] == "mid"]
    # turning points every half period of the damped oscillator, from rest at t = 0
    assert ends == pytest.approx([k * math.pi / omega_d for k in range(1, len(ends) + 1)], abs=1e-9)
    # the rest length first at the root of e^(-g t) (cos w t + g / w sin w t)
    first = (math.pi - math.atan(omega_d / 1.5)) / omega_d
    assert mids[0] == pytest.approx(first, abs=1e-9)
    assert len(ends) == 9 and not [e for e in log if e["kind"] == "collision"]


def test_springs_swing_the_ball_is_flung_up_hits_the_top_and_swings_to_rest(tmp_path: Path) -> None:
    r, log = pge_run(tmp_path, game("springs-swing"), "--until", "5")
    assert r.returncode == 0, r.stderr
    hits = [e for e in log if e["kind"] == "collision"]
    # the stiff short spring to the right anchor flings the ball up into the top border
    # (box-3, its lower face at y = 0.99) once, at a contact point on that face
    assert [(e["a"], e["b"]) for e in hits] == [("circle-6", "box-3")]
    assert hits[0]["point"][1] == pytest.approx(0.99, abs=1e-9)
    # then it swings below the anchors, damped: the springs' turning points keep coming
    assert len([e for e in log if e["kind"] == "spring" and e["what"] == "end"]) > 10
