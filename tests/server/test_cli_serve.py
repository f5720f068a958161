"""`max2code serve` as a command: it listens on loopback, stops on SIGTERM, refuses bad input."""

from __future__ import annotations

import re
import signal
import subprocess
import sys
import urllib.request

from .conftest import ARENA


def test_serves_on_loopback_and_stops_on_sigterm():
    proc = subprocess.Popen([sys.executable, "-m", "max2code", "serve", str(ARENA), "--port", "0"],
                            stderr=subprocess.PIPE, text=True)
    try:
        line = proc.stderr.readline()
        m = re.search(r"http://127\.0\.0\.1:(\d+)/ \(players: player1, player2\)", line)
        assert m, line
        with urllib.request.urlopen(f"http://127.0.0.1:{m.group(1)}/") as r:
            assert r.status == 200
        proc.send_signal(signal.SIGTERM)
        assert proc.wait(20) == 128 + signal.SIGTERM
    finally:
        proc.kill()
        proc.wait()


def test_bad_scene_and_options(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text('[[bodies]]\nshape = "circle"\nposition = [0, 0]\nradius = -1\n')
    r = subprocess.run([sys.executable, "-m", "max2code", "serve", str(bad)], capture_output=True, text=True)
    assert r.returncode == 1 and re.match(rf"{re.escape(str(bad))}:\d+:\d+: error:", r.stderr)
    r = subprocess.run([sys.executable, "-m", "max2code", "serve", str(ARENA), "--player", "wall-top"],
                       capture_output=True, text=True)
    assert r.returncode == 1 and "no dynamic body" in r.stderr
    r = subprocess.run([sys.executable, "-m", "max2code", "serve", str(ARENA), "--port", "70000"],
                       capture_output=True, text=True)
    assert r.returncode == 2 and "--port" in r.stderr
    r = subprocess.run([sys.executable, "-m", "max2code", "serve", str(ARENA), "--rate", "-1"],
                       capture_output=True, text=True)
    assert r.returncode == 2 and "--rate" in r.stderr
    r = subprocess.run([sys.executable, "-m", "max2code", "serve", str(ARENA), "--lookahead", "-1"],
                       capture_output=True, text=True)
    assert r.returncode == 2 and "--lookahead" in r.stderr
