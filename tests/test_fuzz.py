"""Property-based fuzzing: mutated .mxm files give output or `file:line:col: error:` diagnostics,
never a traceback or a hang.

Inputs are the shipped equations (paper figures included) mutated at the byte level: characters
and lines deleted, duplicated or swapped; braces, quotes, NUL, CR, comment markers, keywords and
invalid UTF-8 inserted; the file truncated. Most examples go through the parser (reading the
file, parsing, checking language tags); a few go through the whole CLI with Maxima and a short
--timeout.

Default sizes keep this file well under a minute. A long run (100,000 parser examples, the
scale at which the old grammar's backtracking regular expression hung):
    MAX2CODE_FUZZ_EXAMPLES=100000 MAX2CODE_FUZZ_CLI_EXAMPLES=100 python -m pytest tests/test_fuzz.py

Parser examples are parsed from memory (`decode_source` + `parse_text`, what `parse_file` does
after reading), so the count measures the parser rather than the file system.
"""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import tempfile
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conftest import ROOT

from max2code.diagnostics import Max2CodeError
from max2code.codegen.generate import check_tags
from max2code.front.parse import decode_source, parse_text

SEEDS = sorted((ROOT / "equations").rglob("*.mxm"))
SEED_BYTES = [p.read_bytes() for p in SEEDS]
PARSER_EXAMPLES = int(os.environ.get("MAX2CODE_FUZZ_EXAMPLES", "3000"))
CLI_EXAMPLES = int(os.environ.get("MAX2CODE_FUZZ_CLI_EXAMPLES", "10"))
PARSE_SECONDS = 10  # one parse of a file of a few hundred bytes: far above any honest cost

INSERTS = [b"{", b"}", b"{ }", b'"', b"'", b"''", b"\0", b"\r", b"\r\n", b"\n", b"\t", b"/*",
           b"*/", b"//", b"begin", b"end", b"\nend\n", b"term 0 { a[0] = }", b"term 9 c { }",
           b"polynomial terms 3\n", b"initialise cobol { }", b"function f\n", b"parameters a, a\n",
           b"quit();", b";", b"$", b":", b"(", b")", b"\xff", b"\xc3", b"\xe2\x80\x94", b"\\",
           b"1/t", b"sin(t)", b"t^9", b"%", b"\x1b[0m",
           # what made the old grammar backtrack or could make a scanner quadratic
           b"{" * 200, b"}" * 200, b"{ " * 100 + b"}" * 99, b'\\"' * 200, b"/*" * 200,
           b'"' * 201, b"// {\n" * 50, b"begin\n" * 20, b"\\" * 100, b"?" * 10, b":lisp ",
           b"load(\"" + b'\\"' * 100]

DIAGNOSTIC = re.compile(r"^.+:\d+:\d+: (error|warning|note): \S.*$")  # notes: roles without a variant


@st.composite
def mutated(draw: st.DrawFn) -> bytes:
    data = bytearray(draw(st.sampled_from(SEED_BYTES)))
    for _ in range(draw(st.integers(1, 6))):
        op = draw(st.sampled_from(["del", "dup", "swap", "dline", "dupline", "swapline",
                                   "insert", "truncate", "byte"]))
        n = len(data)
        i = draw(st.integers(0, max(n - 1, 0)))
        if op == "del" and n:
            del data[i: i + draw(st.integers(1, 8))]
        elif op == "dup" and n:
            data[i:i] = data[i: i + draw(st.integers(1, 8))]
        elif op == "swap" and n > 1:
            j = min(i + 1, n - 1)
            data[i], data[j] = data[j], data[i]
        elif op == "insert":
            data[i:i] = draw(st.sampled_from(INSERTS))
        elif op == "truncate":
            del data[i:]
        elif op == "byte":
            data[i:i] = bytes([draw(st.integers(0, 255))])
        elif op in ("dline", "dupline", "swapline"):
            lines = bytes(data).split(b"\n")
            k = draw(st.integers(0, len(lines) - 1))
            if op == "dline":
                del lines[k]
            elif op == "dupline":
                lines.insert(k, lines[k])
            elif k + 1 < len(lines):
                lines[k], lines[k + 1] = lines[k + 1], lines[k]
            data = bytearray(b"\n".join(lines))
    return bytes(data)


@contextmanager
def deadline(seconds: int) -> Iterator[None]:
    """Fail instead of hanging: SIGALRM interrupts a runaway parse."""
    def on_alarm(signum: int, frame: object) -> None:
        raise TimeoutError(f"no answer within {seconds} s: a hang")
    old = signal.signal(signal.SIGALRM, on_alarm)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


def check_diagnostics(exc: Max2CodeError, path: str) -> None:
    assert exc.diagnostics
    for diag in exc.diagnostics:
        text = str(diag)
        assert text.startswith(f"{path}:"), text
        assert DIAGNOSTIC.match(text), text
        assert diag.pos.line >= 1 and diag.pos.col >= 1, text


@settings(max_examples=PARSER_EXAMPLES, deadline=None, derandomize=False,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(mutated())
def test_parser_never_crashes(data: bytes) -> None:
    path = "fuzz.mxm"
    with deadline(PARSE_SECONDS):
        try:
            spec = parse_text(decode_source(data, path), path)
            check_tags(spec)
        except Max2CodeError as exc:
            check_diagnostics(exc, path)
            return
    assert spec.program.statements is not None


@pytest.mark.usefixtures("maxima_exe")
@settings(max_examples=CLI_EXAMPLES, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(mutated(), st.sampled_from(["c", "python", "rust", "m2"]))
def test_cli_never_crashes(data: bytes, lang: str) -> None:
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "fuzz.mxm"
        path.write_bytes(data)
        out = Path(tmp) / "out.txt"
        proc = subprocess.run(
            [sys.executable, "-m", "max2code", f"--lang={lang}", str(path), "-o", str(out),
             "--timeout", "10", "--no-cache"],
            cwd=ROOT, capture_output=True, text=True, timeout=120,
            env={**os.environ, "MAX2CODE_CACHE": str(Path(tmp) / "cache")})
        assert "Traceback" not in proc.stderr and "internal error" not in proc.stderr, proc.stderr
        assert proc.returncode in (0, 1), proc.stderr
        for line in proc.stderr.splitlines():
            assert DIAGNOSTIC.match(line) and line.startswith(f"{path}:"), line
        if proc.returncode == 0:
            assert out.exists()
        else:
            assert proc.stderr and not out.exists()
