"""Where the templates and runtimes live: beside the package in a checkout or editable install."""

from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def templates_dir() -> Path:
    return ROOT / "templates"


def runtime_dir(lang: str) -> Path:
    return ROOT / "runtime" / lang
