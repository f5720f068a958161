"""Wide and deep expressions: a sum of any length is handled without recursion, nesting is
bounded by MAX_DEPTH with a diagnostic, and everything up to that bound goes through the
printers, the optimiser and the operation counts without Python's RecursionError.

The oracle for the printed values is Python evaluating Maxima's own text (`^` read as `**`),
which shares nothing with max2code's parser, trees or printers.
"""

from __future__ import annotations

import math
import os
import random
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT

from max2code.codegen.expr import MAX_DEPTH, Add, ExprSyntaxError, parse_maxima
from max2code.languages import LANGUAGES
from max2code.codegen.straight import count_ops
from max2code.codegen.tpoly import optimise


def oracle(text: str, values: dict[str, float]) -> float:
    return float(eval(text.replace("^", "**"), {"sin": math.sin, "cos": math.cos}, values))


def printed(text: str, values: dict[str, float]) -> float:
    code = LANGUAGES["python"].expr(parse_maxima(text))
    return float(eval(code, {"math": math}, values))


def test_a_sum_of_a_hundred_thousand_terms() -> None:
    """Parsed without recursion; printed for Python as math.fsum (CPython cannot compile a
    chain of 3000 additions); its value against a plain loop over the terms."""
    text = " + ".join(f"{k}*x{k % 7}*y" for k in range(1, 100_001))
    e = parse_maxima(text)
    assert isinstance(e, Add) and len(e.args) == 100_000
    values = {f"x{k}": 1.0 + k / 8 for k in range(7)} | {"y": 0.5}
    expected = math.fsum(k * values[f"x{k % 7}"] * values["y"] for k in range(1, 100_001))
    assert printed(text, values) == pytest.approx(expected, rel=1e-12)
    assert count_ops(e).add == 99_999
    for lang in LANGUAGES.values():
        assert lang.expr(e)


def nested(levels: int) -> str:
    """Maxima text nesting sums, products, powers, signs and calls `levels` times."""
    text = "z"
    for k in range(levels):
        text = f"(x{k % 5} - {k + 1}*sin({text})^2/3)"
    return text


def test_nesting_up_to_the_bound_prints_optimises_and_counts() -> None:
    levels = 1
    while True:  # the deepest text of this shape that is accepted
        try:
            parse_maxima(nested(levels + 1))
        except ExprSyntaxError:
            break
        levels += 1
    text = nested(levels)
    e = parse_maxima(text)
    values = {f"x{k}": 0.1 * (k + 1) for k in range(5)} | {"z": 0.7}
    assert printed(text, values) == pytest.approx(oracle(text, values), rel=1e-12)
    for lang in LANGUAGES.values():
        assert lang.expr(e)  # no RecursionError in any printer
    assert count_ops(e).call == levels
    assert optimise(parse_maxima(f"t*{text} + t^2"), "t", 2).outputs


def test_nesting_beyond_the_bound_is_a_diagnostic() -> None:
    assert parse_maxima("(a + " * (MAX_DEPTH - 1) + "b" + ")" * (MAX_DEPTH - 1))
    with pytest.raises(ExprSyntaxError, match=rf"nested {MAX_DEPTH + 1} levels deep .* at most "
                                              rf"{MAX_DEPTH}: simplify it"):
        parse_maxima("(a + " * MAX_DEPTH + "b" + ")" * MAX_DEPTH)


def test_a_500_term_equation_end_to_end(tmp_path: Path, maxima_exe: str) -> None:
    """Issue 12: a 500-term sum exited 2 with RecursionError."""
    names = [f"x{k}" for k in range(500)]
    mxm = tmp_path / "wide.mxm"
    mxm.write_text("function wide\nbegin\n(t - (" + " + ".join(names) + "))*(t + 1);\nend\n")
    out = tmp_path / "wide.py"
    proc = subprocess.run([sys.executable, "-m", "max2code", "--lang=python", str(mxm), "-o",
                           str(out)], cwd=ROOT, capture_output=True, text=True, timeout=600,
                          env={**os.environ, "MAX2CODE_CACHE": str(tmp_path / "cache")})
    assert proc.returncode == 0, proc.stderr
    module: dict[str, object] = {}
    exec(out.read_text(), module)
    rng = random.Random(12)
    p = {n: rng.uniform(-1, 1) for n in names}
    s = sum(p[n] for n in module["PARAMS"])  # type: ignore[union-attr]
    c = module["coefficients"]([p[n] for n in module["PARAMS"]])  # type: ignore[operator, union-attr]
    # (t - s)(t + 1) = t^2 + (1 - s) t - s
    assert c == pytest.approx([-s, 1 - s, 1.0], rel=1e-12, abs=1e-12)


def test_a_constant_beyond_a_double_is_a_diagnostic_not_a_crash() -> None:
    """(t - 1)^2000's middle coefficients exceed 1.8e308: an OverflowError used to exit 2."""
    for lang in LANGUAGES.values():
        with pytest.raises(ValueError, match=r"the constant 2\.048e\+600 does not fit in a double"):
            lang.expr(parse_maxima(str(math.comb(2000, 1000)) + "*x"))


def test_powers_above_maxposex_are_expanded(tmp_path: Path, maxima_exe: str,
                                            monkeypatch: pytest.MonkeyPatch) -> None:
    """Maxima's expand() leaves a power above maxposex (1000) alone, which made (t - 1)^1001
    look like a coefficient holding t. Checked against math.comb."""
    from max2code.front.parse import parse_text
    from max2code.codegen.poly import polynomial

    monkeypatch.setenv("MAX2CODE_CACHE", str(tmp_path))
    spec = parse_text("begin\n(t - 1)^1001;\nend\n", str(tmp_path / "p.mxm"))
    poly = polynomial(spec, combos=[((), ())])
    assert poly.degree == 1001
    for k in (0, 1, 500, 1001):
        c = poly.coefficients[k]
        value = c.value if hasattr(c, "value") else -c.arg.value  # type: ignore[union-attr]
        assert value == (-1) ** (1001 - k) * math.comb(1001, k)
