"""Helpers for the PGE tests: the corpus's place and a headless run with its event log."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
CORPUS = Path(os.environ.get("PGE_CORPUS", ROOT.parent / "shared" / "corpus" / "pge-python"))


def pge_run(tmp: Path, game: str, *args: str, log_name: str = "log.jsonl"):
    """`max2code pge GAME --headless --events LOG ARGS`: (the completed process, the log's
    records or None when none was written)."""
    log = tmp / log_name
    if log.exists():
        log.unlink()
    env = dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    r = subprocess.run([sys.executable, "-m", "max2code", "pge", game, "--headless",
                        "--events", str(log), *args], capture_output=True, text=True,
                       timeout=600, env=env, cwd=tmp)
    records = [json.loads(x) for x in log.read_text().splitlines()] if log.exists() else None
    return r, records
