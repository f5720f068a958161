"""The engine core under AddressSanitizer and UndefinedBehaviorSanitizer (issue 33, item 10).

The core is built again with -fsanitize=address,undefined -fno-sanitize-recover=all (from the
equation headers of the ordinary build) and scenes run through it, hostile ones included:
any finding aborts the run (compound bodies too). The hostile numbers the Python API refuses
(limits.py) reach the core through its C API (cffi), as a C program could give them. Found
before: memmove(NULL, ..., 0) on every step (world.c), and
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
    # Hostile numbers the Python API refuses (limits.py, as scene files do) go to the core
    # through its own C API, as a C program could give them: the core must hold them too.
    from max2code.engine.binding import load
    ffi, lib = load()

    def core_world(tolerance=1e-9, max_events=20000, contact_step=1 / 240):
        cfg = ffi.new("m2c_config *")
        cfg.tolerance, cfg.max_events, cfg.contact_step = tolerance, max_events, contact_step
        return ffi.gc(lib.m2c_world_new(cfg), lib.m2c_world_free)

    def core_body(w, vertices=(), radius=0.0, kind=2, position=(0, 0), velocity=(0, 0),
                  omega=0.0, gravity=(0, 0), parts=(), mass=1.0, inertia=1.0):
        d = ffi.new("m2c_body_def *", lib.m2c_default_body_def())
        d.kind, (d.x, d.y), (d.vx, d.vy), d.omega = kind, position, velocity, omega
        (d.ax, d.ay), d.mass, d.inertia = (gravity if kind else (0, 0)), mass, inertia
        flats = [ffi.new("double[]", [c for p in v for c in p]) for v, _ in parts or [(vertices, radius)]]
        if parts:
            cparts = ffi.new("m2c_part[]", len(parts))
            for k, ((v, r), flat) in enumerate(zip(parts, flats)):
                cparts[k].nvertices, cparts[k].vertices, cparts[k].radius = len(v), flat, r
            d.nparts, d.parts = len(parts), cparts
        else:
            d.nvertices, d.vertices, d.radius = len(vertices), flats[0], radius
        if lib.m2c_world_add_body(w, d) < 0:
            print("refused:", ffi.string(lib.m2c_world_error(w)).decode())

    def core_run(w, t=2.0):
        buf, n = ffi.new("m2c_event[]", 64), ffi.new("int *")
        while True:
            status = lib.m2c_world_step(w, t, buf, 64, n)
            if status < 0:
                print("refused:", ffi.string(lib.m2c_world_error(w)).decode())
            if status <= 0:
                return

    def core_scene(tolerance=1e-9):
        w = core_world(tolerance)
        for a, b in (((-5, 0), (5, 0)), ((-5, 0), (-5, 10)), ((5, 0), (5, 10))):
            core_body(w, (a, b), kind=0)
        return w

    G = (0, -9.81)
    for big in (1e308, -1e308, 1e300):              # hostile coordinates and tolerances
        try:
            World().add_circle((big, 1), 1.0)
            raise SystemExit("the API took a coordinate of %g" % big)
        except EngineError:
            pass
        w = core_scene()
        core_body(w, [(0, 0)], 1.0, position=(big, 1), velocity=(0, 3), gravity=G)
        core_body(w, [(0, 0)], 1.0, position=(0, 3), gravity=G)
        core_run(w)
        w = core_scene(tolerance=abs(big))
        core_body(w, [(0, 0)], 1.0, position=(0, 3), gravity=G)
        core_run(w)
    w = core_world()                                # huge gravity, spin, length
    core_body(w, [(-5, 0), (5, 0)], kind=0)
    core_body(w, [(0, 0)], 0.5, position=(0, 2), gravity=(0, -1e308))
    core_run(w)
    w = core_world()
    core_body(w, [(-5, 0), (5, 0)], kind=0)
    core_body(w, [(-1, -1), (1, -1), (1, 1), (-1, 1)], position=(0, 3), omega=1e308)
    core_run(w)
    w = core_scene()
    core_body(w, [(-5e14, 0), (5e14, 0)], 0.5, position=(0, 3), omega=1, gravity=G)
    core_run(w)
    w = core_world()                                # a mass beyond doubles lands
    core_body(w, [(-5, 0), (5, 0)], kind=0)
    core_body(w, [(0, 0)], 0.5, position=(0, 2), gravity=G, mass=1e308, inertia=1e308)
    core_body(w, [(0, 0)], 0.5, position=(3, 2), gravity=G, mass=1e-300, inertia=1e-300)
    core_run(w)
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
    for parts, kw in [([([(1e300, 0.0)], 0.5), ([(-1e300, 0.0)], 0.5)], dict()),
                      ([([(-5e14, 0.0), (5e14, 0.0)], 0.1), ([(0.0, 0.0)], 0.5)], dict(omega=1)),
                      ([([(-0.5, 0.0)], 0.2), ([(0.5, 0.0)], 0.2)], dict(omega=1e308))]:
        w = core_world()                              # hostile compounds: far, long, spin
        core_body(w, [(-100, 0), (100, 0)], kind=0)
        core_body(w, parts=parts, position=(0, 3), gravity=G, **kw)
        core_run(w, 1.0)
    w = World(gravity=(0, -9.81), max_events=20000)   # the most parts, through the API
    w.add_segment((-100, 0), (100, 0))
    w.add_compound([([(0.01 * k, 0.0)], 0.1) for k in range(128)], position=(0, 3), omega=3)
    run(w, 1.0)
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


MISUSE = r"""
#include <limits.h>
#include <stdio.h>
#include "max2code_engine.h"

static void show(m2c_world *w, const char *what, int r)
{
    printf("%s: %d %s\n", what, r, r < 0 ? m2c_world_error(w) : "");
}

int main(void)
{
    m2c_config cfg = {0};
    m2c_world *w = m2c_world_new(&cfg);
    double c0[] = {0, 0}, c1[] = {1, 0}, nanv[] = {0.0 / 0.0, 0};
    m2c_part good[] = {{1, c0, 0.25}, {1, c1, 0.25}};
    m2c_body_def d = m2c_default_body_def();
    d.nparts = 2;
    show(w, "parts NULL", m2c_world_add_body(w, &d));
    d.nparts = INT_MIN;
    d.parts = good;
    show(w, "nparts INT_MIN", m2c_world_add_body(w, &d));
    m2c_part none[] = {{0, NULL, 0.25}};
    d.nparts = 1;
    d.parts = none;
    show(w, "no vertices", m2c_world_add_body(w, &d));
    m2c_part huge[] = {{INT_MAX, c0, 0.25}};      /* 2 * n overflowed int before reading */
    d.parts = huge;
    show(w, "INT_MAX vertices", m2c_world_add_body(w, &d));
    m2c_part sum[] = {{INT_MAX / 2 + 10, nanv, 0.1}, {INT_MAX / 2 + 10, nanv, 0.1}};
    d.nparts = 2;
    d.parts = sum;
    show(w, "counts past INT_MAX", m2c_world_add_body(w, &d));
    m2c_body_def zero = {0};
    zero.nparts = 2;
    zero.parts = good;
    show(w, "zeroed def", m2c_world_add_body(w, &zero));
    d.parts = good;
    int id = m2c_world_add_body(w, &d);
    show(w, "good", id);
    double radii[1];
    show(w, "parts NULL, capacity 0", m2c_world_parts(w, id, NULL, NULL, 0));
    show(w, "radii only, capacity 1", m2c_world_parts(w, id, NULL, radii, 1));
    printf("radius: %g\n", radii[0]);
    show(w, "counts and radii NULL, capacity 2", m2c_world_parts(w, id, NULL, NULL, 2));
    show(w, "capacity -1", m2c_world_parts(w, id, NULL, NULL, -1));
    show(w, "no such body", m2c_world_parts(w, 7, NULL, NULL, 2));
    m2c_world_free(w);
    return 0;
}
"""


def test_c_api_misuse_of_compounds_is_refused_clean(sanitized, tmp_path):
    """Compound defs misused from C, built with the sanitizers against the sanitized core:
    each is a named refusal (found: a part of INT_MAX vertices overflowed 2 * n in int before
    anything was read, and m2c_world_parts wrote through NULL buffers), and no finding."""
    from max2code.engine.build import engine_dir
    lib, _ = sanitized
    (tmp_path / "misuse.c").write_text(MISUSE)
    exe = tmp_path / "misuse"
    subprocess.run(["cc", "-std=c11", "-g", SANITIZE, "-fno-sanitize-recover=all",
                    f"-I{engine_dir() / 'include'}", str(tmp_path / "misuse.c"), "-o", str(exe),
                    str(lib), f"-Wl,-rpath,{lib.parent}", "-lm"], check=True, capture_output=True)
    proc = subprocess.run([str(exe)], capture_output=True, text=True, timeout=300,
                          env=dict(os.environ, ASAN_OPTIONS="detect_leaks=1"))
    report = proc.stdout + proc.stderr
    assert proc.returncode == 0 and "runtime error" not in report, report[-4000:]
    lines = dict(line.split(": ", 1) for line in proc.stdout.splitlines())
    assert lines["parts NULL"] == "-1 a compound body needs its parts (nparts >= 1 and parts)"
    assert lines["nparts INT_MIN"].startswith("-1 a compound body needs its parts")
    assert lines["no vertices"] == "-1 part 0 of 1: a body needs at least one vertex"
    assert lines["INT_MAX vertices"] == "-1 part 0 of 1: a body has at most 16777216 vertices"
    assert lines["counts past INT_MAX"] == "-1 part 0 of 2: a body has at most 16777216 vertices"
    assert lines["zeroed def"].startswith("-1 the body def was not made by m2c_default_body_def")
    assert lines["good"] == "0 "
    assert lines["parts NULL, capacity 0"] == "2 "
    assert lines["radius"] == "0.25"
    assert lines["counts and radii NULL, capacity 2"] == "2 "
    assert lines["capacity -1"] == "2 "
    assert lines["no such body"].startswith("-1")
