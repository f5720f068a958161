"""`max2code sim` without --events keeps no events (issue 33, item 8): they are counted as they
stream by. Before, a 400-disc gas run for 200 s held 296 MB (26 MB now); here 80 s, about
180,000 collisions, must stay under 60 MB where it took some 130 MB.

The peak is the run's own: VmHWM, the high-water mark of the process's memory since its exec,
which it reports at exit. os.wait4's ru_maxrss was used before, and it is not the child's own: a
forked (or vforked) child's exec records the parent's resident size as its peak, so the test
measured pytest itself -- 111 MB in CI's whole-suite run, 79 MB in a run of tests/engine, the
26 MB of the simulation only in a run of this file. The run loads a copy of the library the
fixture built (MAX2CODE_ENGINE_LIB), so it never builds one either."""

from __future__ import annotations

import json
import os
import random
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT

# `python -m max2code ARGS`, then the process's peak resident size (kB) on stderr's last line
PEAK_OF_RUN = """
import atexit, runpy, sys
def peak():
    status = open("/proc/self/status").read()
    sys.stderr.write("\\nVmHWM " + status.split("VmHWM:")[1].split()[0] + "\\n")
atexit.register(peak)
sys.argv = ["max2code", *sys.argv[1:]]
runpy.run_module("max2code", run_name="__main__")
"""


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


@pytest.mark.skipif(not Path("/proc/self/status").exists(), reason="VmHWM is Linux's")
def test_sim_without_events_streams_them(engine, tmp_path):
    from max2code.engine.build import library
    scene = tmp_path / "gas.toml"
    gas_scene(scene, 80)
    lib = tmp_path / library().name
    shutil.copy(library(), lib)
    env = dict(os.environ, MAX2CODE_ENGINE_LIB=str(lib))   # nothing to build in the run
    proc = subprocess.run([sys.executable, "-c", PEAK_OF_RUN, "sim", str(scene), "--json"],
                          cwd=ROOT, env=env, capture_output=True, text=True, timeout=600)
    # the count is kept: every collision is reported
    assert proc.returncode == 0, proc.stderr
    summary = json.loads(proc.stdout)
    assert summary["reported"] == summary["collisions"] > 100_000
    peak = re.fullmatch(r"VmHWM (\d+)", proc.stderr.strip().splitlines()[-1])
    assert peak, proc.stderr
    assert 10 * 1024 < int(peak[1]) < 60 * 1024, f"peak {int(peak[1]) / 1024:.0f} MB"
