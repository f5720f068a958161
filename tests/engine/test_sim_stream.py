"""`max2code sim` without --events keeps no events (issue 33, item 8): they are counted as they
stream by. Before, a 400-disc gas run for 200 s held 296 MB (26 MB now); here 80 s, about
180,000 collisions, must stay under 60 MB where it took some 130 MB."""

from __future__ import annotations

import json
import os
import random
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
    scene = tmp_path / "gas.toml"
    gas_scene(scene, 80)
    proc = subprocess.Popen([sys.executable, "-m", "max2code", "sim", str(scene), "--json"],
                            cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    out, err = proc.communicate(timeout=600)
    # the count is kept: every collision is reported
    assert proc.returncode == 0, err
    summary = json.loads(out)
    assert summary["reported"] == summary["collisions"] > 100_000
    # the peak memory of a run of its own (os.wait4 gives that child's own rusage)
    pid = os.fork()
    if pid == 0:  # pragma: no cover - the child
        try:
            os.chdir(ROOT)
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, 1)
            os.execv(sys.executable, [sys.executable, "-m", "max2code", "sim", str(scene)])
        finally:
            os._exit(127)
    _, status, usage = os.wait4(pid, 0)
    assert os.waitstatus_to_exitcode(status) == 0
    assert usage.ru_maxrss < 60 * 1024, f"peak {usage.ru_maxrss / 1024:.0f} MB"
