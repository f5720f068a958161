"""`max2code sim` without --events keeps no events (issue 33, item 8): they are counted as they
stream by. Before, a 400-disc gas run for 200 s held 296 MB (26 MB now); here 80 s, about
180,000 collisions, must stay under 60 MB where it took some 130 MB.

Both runs load the library the fixture built, from a copy of their own (MAX2CODE_ENGINE_LIB):
os.wait4's peak includes the child's own children, and a run that found the library pruned
from the shared cache (other clones' builds, tests/engine/test_build_cache.py) built it again
inside the measured run -- the compiler's 111 MB was reported as the simulation's (357 MB when
Maxima ran too)."""

from __future__ import annotations

import json
import os
import random
import shutil
import subprocess
import sys

from conftest import ROOT


def gas_scene(path, until: float) -> None:
    rng = random.Random(3)
    lines = ['name = "gas"', f"until = {until}", ""]
    size = 10
    corners = [(0, 0), (size, 0), (size, size), (0, size)]
    for k in range(4):
        (ax, ay), (bx, by) = corners[k], corners[(k + 1) % 4]
        lines += ["[[bodies]]", 'kind = "static"', 'shape = "segment"',
                  f"points = [[{ax}, {ay}], [{bx}, {by}]]", ""]
    for i in range(20):
        for j in range(20):
            lines += ["[[bodies]]", 'shape = "circle"', f"position = [{0.25 + i * 0.5}, {0.25 + j * 0.5}]",
                      "radius = 0.1", f"velocity = [{rng.uniform(-5, 5):.3f}, {rng.uniform(-5, 5):.3f}]", ""]
    path.write_text("\n".join(lines))


def test_sim_without_events_streams_them(engine, tmp_path):
    from max2code.engine.build import library
    scene = tmp_path / "gas.toml"
    gas_scene(scene, 80)
    lib = tmp_path / library().name
    shutil.copy(library(), lib)
    env = dict(os.environ, MAX2CODE_ENGINE_LIB=str(lib))   # nothing to build in the runs
    proc = subprocess.Popen([sys.executable, "-m", "max2code", "sim", str(scene), "--json"],
                            cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    out, err = proc.communicate(timeout=600)
    # the count is kept: every collision is reported
    assert proc.returncode == 0, err
    summary = json.loads(out)
    assert summary["reported"] == summary["collisions"] > 100_000
    # the peak memory of a run of its own (os.wait4 gives that child's rusage, with its children's:
    # it has none now)
    pid = os.fork()
    if pid == 0:  # pragma: no cover - the child
        try:
            os.chdir(ROOT)
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, 1)
            os.execve(sys.executable, [sys.executable, "-m", "max2code", "sim", str(scene)], env)
        finally:
            os._exit(127)
    _, status, usage = os.wait4(pid, 0)
    assert os.waitstatus_to_exitcode(status) == 0
    assert usage.ru_maxrss < 60 * 1024, f"peak {usage.ru_maxrss / 1024:.0f} MB"
