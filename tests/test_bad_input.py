"""The catalogue of bad input: tests/bad/NAME.mxm gives exit 1, exactly the diagnostic line in
tests/bad/NAME.expected (paths as seen from the repository root), no traceback, and leaves a
previous output file byte-identical with the same mtime. tests/good/ holds awkward but valid
input (CRLF and CR endings, tabs, a byte-order mark, non-ASCII comments).

A few entries need a condition beyond the file itself, given in SPECIAL: a short --timeout,
no Maxima on PATH, an output folder that cannot be written, a file that does not exist.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT

BAD = ROOT / "tests" / "bad"
GOOD = ROOT / "tests" / "good"
NAMES = sorted(p.stem for p in BAD.glob("*.expected"))

# name -> (extra arguments, output path relative to ROOT or None for a temporary file)
SPECIAL: dict[str, tuple[list[str], str | None]] = {
    "maxima-timeout": (["--timeout", "4"], None),
    "maxima-out-of-memory": (["--maxima-memory", "300", "--timeout", "100"], None),
    "unwritable-output": ([], "tests/bad/unwritable-output.mxm/out.h"),  # a file as a folder
}
NEEDS_NO_MAXIMA = {"no-maxima"}
NEEDS_NO_FILE = {"missing-file"}
NO_MAXIMA_NEEDED = {  # diagnosed before Maxima runs
    "binary-garbage", "empty-file", "not-utf8", "missing-file", "unterminated-block",
    "unterminated-begin", "unterminated-brace-program", "stray-brace", "missing-term",
    "duplicate-term", "out-of-order-terms", "term-beyond-count", "zero-terms",
    "duplicate-declaration", "parameter-twice", "unknown-language-tag", "unterminated-string",
    "unterminated-comment", "unterminated-statement", "empty-program", "header-garbage",
    "no-maxima",
    # names Maxima gives a value (max2code/maxima/names.py), a name too long
    "parameter-maxima-option", "maxima-option-read", "parameter-maxima-flag",
    "maxima-system-variable", "name-too-long",
    # refused by the lock-down before Maxima runs (max2code/maxima/lockdown.py)
    "unsafe-backslash", "unsafe-eval-string", "unsafe-lisp", "unsafe-lisp-after-comment",
    "unsafe-load-computed", "unsafe-load-lisp", "unsafe-load-outside", "unsafe-load-parent",
    "unsafe-load-variable", "unsafe-map-system", "unsafe-plot", "unsafe-question-mark",
    "unsafe-system", "unsafe-system-as-value", "unsafe-with-stdout", "unsafe-writefile",
}


def test_catalogue_is_big_enough() -> None:
    assert len(NAMES) >= 25
    for name in NAMES:
        assert (BAD / f"{name}.mxm").exists() == (name not in NEEDS_NO_FILE), name


@pytest.mark.parametrize("name", NAMES)
def test_bad_input(name: str, tmp_path: Path, request: pytest.FixtureRequest) -> None:
    if name not in NO_MAXIMA_NEEDED:
        request.getfixturevalue("maxima_exe")
    expected = (BAD / f"{name}.expected").read_text(encoding="utf-8").rstrip("\n")
    assert "\n" not in expected
    extra, out_rel = SPECIAL.get(name, ([], None))
    out = ROOT / out_rel if out_rel else tmp_path / "previous.h"
    previous = b"/* previous output */\n"
    if out_rel is None:
        out.write_bytes(previous)
        os.utime(out, ns=(1_000_000_000, 1_000_000_000))
    env = {**os.environ, "MAX2CODE_CACHE": str(tmp_path / "cache")}
    if name in NEEDS_NO_MAXIMA:
        env.pop("MAXIMA", None)
        env["PATH"] = str(tmp_path)  # nothing on it
    mxm = f"tests/bad/{name}.mxm"
    source_before = (ROOT / mxm).read_bytes() if (ROOT / mxm).exists() else None
    proc = subprocess.run([sys.executable, "-m", "max2code", "--lang=c", mxm, "-o",
                           out_rel or str(out), *extra], cwd=ROOT, env=env, capture_output=True,
                          text=True, timeout=120)
    assert proc.returncode == 1, proc.stderr
    assert "Traceback" not in proc.stderr
    assert proc.stderr.splitlines()[0] == expected
    assert proc.stdout == ""
    if out_rel is None:
        assert out.read_bytes() == previous
        assert out.stat().st_mtime_ns == 1_000_000_000
        assert sorted(p.name for p in tmp_path.iterdir() if p.name != "cache") == ["previous.h"]
    else:
        assert not out.exists()
    if source_before is not None:
        assert (ROOT / mxm).read_bytes() == source_before


@pytest.mark.parametrize("lang", ["c", "python"])
@pytest.mark.parametrize("name", sorted(p.name for p in GOOD.glob("*.mxm")))
def test_awkward_but_valid_input(name: str, lang: str, tmp_path: Path, maxima_exe: str) -> None:
    raw = (GOOD / name).read_bytes()
    assert b"\r" in raw  # the point of these files
    out = tmp_path / ("out.h" if lang == "c" else "out.py")
    proc = subprocess.run([sys.executable, "-m", "max2code", f"--lang={lang}", f"tests/good/{name}",
                           "-o", str(out)], cwd=ROOT, capture_output=True, text=True, timeout=120,
                          env={**os.environ, "MAX2CODE_CACHE": str(tmp_path / "cache")})
    assert proc.returncode == 0, proc.stderr
    assert proc.stderr == ""
    text = out.read_text()
    assert "DEGREE 2" in text or "DEGREE = 2" in text
    assert "\r" not in text


@pytest.mark.parametrize("text,shown,caret,expected", [
    ("x: 1 +* 2;", "x:Space1Space+*Space", "      ^", (5, 17)),
    ("y: a +\n    (b *) + 1;", "SpaceSpaceSpaceSpace(bSpace*)", "       ^", (6, 8)),
    ("w: f(\u00e9 b);", "w:Spacef(\\303\\251Spaceb)", "        ^", (5, 18)),  # a byte offset
    ("w: f(a\tb);", "w:Spacef(aTabb)", "       ^", (5, 18)),
    ("x: 1 +* 2;", "something else", "      ^", (5, 11)),  # not found: the statement
])
def test_maxima_syntax_error_columns(text: str, shown: str, caret: str,
                                     expected: tuple[int, int]) -> None:
    """Maxima's caret (a byte offset into the line it shows, spaces printed as 'Space') is
    mapped back to the .mxm; here the statement starts at line 5, column 11."""
    from max2code.diagnostics import Pos
    from max2code.maxima.session import syntax_error_pos
    from max2code.front.spec import Statement

    pos = syntax_error_pos(Statement(text, Pos("f.mxm", 5, 11)), shown, caret)
    assert (pos.line, pos.col) == expected
