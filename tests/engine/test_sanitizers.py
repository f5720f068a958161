"""The engine core under AddressSanitizer and UndefinedBehaviorSanitizer (issue 33, item 10).

The core is built again with -fsanitize=address,undefined -fno-sanitize-recover=all (from the
equation headers of the ordinary build) and scenes run through it, hostile ones included:
any finding aborts the run (compound bodies too). Found before: memmove(NULL, ..., 0) on every step (world.c), and
coordinates or a tolerance of +-1e308 reaching (int)NaN and a signed overflow in grid.c.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import textwrap

import pytest

from conftest import ROOT

SANITIZE = "-fsanitize=address,undefined"

SCENES = textwrap.dedent("""
    import math, random
    from max2code.engine import World, EngineError

    def scene(**kw):
        w = World(gravity=(0, -9.81), **kw)
        w.add_segment((-5, 0), (5, 0))
        w.add_segment((-5, 0), (-5, 10))
        w.add_segment((5, 0), (5, 10))
        return w

    def run(w, t=2.0):
        try:
            w.step_to(t)
        except EngineError as exc:
            print("refused:", exc)

    w = scene()                                     # an ordinary bouncing ball and a box
    w.add_circle((0, 1), 0.5, velocity=(1, 4), restitution=0.9)
    w.add_polygon([(-0.3, -0.2), (0.3, -0.2), (0.3, 0.2), (-0.3, 0.2)], position=(2, 3), omega=3)
    w.add_timer(0.5); w.add_timer(0.25); w.add_timer(1.5)
    run(w)
    rng = random.Random(1)                          # a small pile
    w = scene()
    for k in range(30):
        w.add_circle((-4 + 0.27 * k, 1 + 0.3 * (k % 5)), 0.12, restitution=0.5)
    run(w, 3.0)
    for big in (1e308, -1e308, 1e300):              # hostile coordinates and tolerances
        w = scene()
        w.add_circle((big, 1), 1.0, velocity=(0, 3))
        w.add_circle((0, 3), 1.0)
        run(w)
        w = scene(tolerance=abs(big))
        w.add_circle((0, 3), 1.0)
        run(w)
    w = World(gravity=(0, -1e308))                  # huge gravity, spin, length
    w.add_segment((-5, 0), (5, 0))
    w.add_circle((0, 2), 0.5)
    run(w)
    w = World(max_events=20000)
    w.add_segment((-5, 0), (5, 0))
    w.add_polygon([(-1, -1), (1, -1), (1, 1), (-1, 1)], position=(0, 3), omega=1e308)
    run(w)
    w = scene()
    w.add_segment((-5e14, 0), (5e14, 0), radius=0.5, kind="dynamic", position=(0, 3), omega=1)
    run(w)
    w = World()                                     # a piston crushing a ball
    w.add_segment((0, -1), (0, 1))
    w.add_circle((1, 0), 0.1, velocity=(-3, 0))
    w.add_body([(0, -1), (0, 1)], kind="kinematic", position=(2, 0), velocity=(-1, 0))
    run(w)
    import copy, pickle                             # compound bodies (the parts' tables),
    for step in (0.0, 1 / 240):                     # a snapshot, queries, the contact solver
        w = scene(contact_step=step)
        w.add_compound([([(-0.5, 0.0)], 0.2), ([(0.5, 0.0)], 0.2), ([(-0.5, 0), (0.5, 0)], 0.05)],
                       position=(0, 2), omega=4, velocity=(3, 0), restitution=0.5)
        w.add_compound([([(0, 0), (1, 0), (1, 0.4), (0, 0.4)], 0.0), ([(0, 0.4), (0.4, 0.4), (0, 1.2)], 0.1)],
                       position=(-3, 1), omega=-2, restitution=0.5)
        w.add_compound([([(1, 0.5), (2, 0.5)], 0.0), ([(1.5, 1.0)], 0.3)], kind="static")
        run(w, 1.0)
        w2 = pickle.loads(pickle.dumps(w)); run(w2, 3.0)
        w.query_point((0, 1)); w.query_box((-5, 0), (5, 5)); w.cast_ray((-5, 1), (5, 1))
    print("ok")
""")


@pytest.fixture(scope="module")
def sanitized(engine, tmp_path_factory):
    """The core built with the sanitizers, and the runtime library they need preloaded."""
    from max2code.engine.build import engine_dir, library
    from max2code.paths import runtime_dir

    asan = subprocess.run(["cc", "-print-file-name=libasan.so"], capture_output=True,
                          text=True).stdout.strip()
    if not os.path.isabs(asan):
        message = "the C compiler has no libasan (gcc's AddressSanitizer)"
        if os.environ.get("CI"):
            pytest.fail(message + " -- required in CI")
        pytest.skip(message)
    out = tmp_path_factory.mktemp("sanitized")
    shutil.copytree(library().parent / "gen", out / "gen")  # the equation headers, as built
    flags = f"-O1 -g {SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer"
    proc = subprocess.run(["make", "-s", "-C", str(engine_dir()), f"BUILD={out}",
                           f"MAX2CODE={sys.executable} -m max2code", f"RUNTIME={runtime_dir('c')}",
                           f"EQUATIONS={ROOT / 'equations'}", f"CFLAGS={flags}",
                           f"LDFLAGS={SANITIZE}"], capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return out / "libmax2code_engine.so", asan


def test_scenes_run_clean_under_asan_and_ubsan(sanitized):
    lib, asan = sanitized
    env = dict(os.environ, MAX2CODE_ENGINE_LIB=str(lib), LD_PRELOAD=asan,
               ASAN_OPTIONS="detect_leaks=0:abort_on_error=0",
               UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1")
    proc = subprocess.run([sys.executable, "-c", SCENES], capture_output=True, text=True,
                          env=env, cwd=ROOT, timeout=900)
    report = proc.stdout + proc.stderr
    assert "runtime error" not in report and "AddressSanitizer" not in report, report[-4000:]
    assert proc.returncode == 0 and proc.stdout.rstrip().endswith("ok"), report[-4000:]
