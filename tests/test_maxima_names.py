"""Names Maxima gives a value (issue 33, item 9): a parameter named fpprec was replaced by 16
and expop removed the t^2 term, with exit status 0, and `check` passed because the oracle ran
the same program. Now such a name is an error where it stands, and the oracle renames the
parameters before it runs, so it computes the equation as written even where the check misses."""

from __future__ import annotations

import dataclasses
import subprocess
from fractions import Fraction

import pytest

from conftest import ROOT
from max2code.maxima import session as maxima, names as maxima_names
from max2code.commands import oracle
from max2code.diagnostics import Max2CodeError
from max2code.front.parse import parse_text
from max2code.front.spec import Declared

# the names the issue found, and a few of each kind
FOUND = ["fpprec", "expop", "linel", "maxposex", "ibase", "fpprintprec", "ratepsilon",
         "gensumnum", "float", "__", "numer", "domain", "gcd", "values"]


def program(text: str, params: str | None = None) -> str:
    head = f"parameters {params}\n" if params else ""
    return f"{head}begin\n  {text}\nend\n"


@pytest.mark.parametrize("name", FOUND)
def test_declared_is_an_error_at_it(name: str) -> None:
    with pytest.raises(Max2CodeError) as info:
        parse_text(program(f"x + v*t + {name}*t^2;", f"x, v, {name}"), "eq.mxm")
    assert str(info.value).startswith(f"eq.mxm:1:18: error: '{name}' is "), str(info.value)
    assert "of Maxima" in str(info.value) and "rename it" in str(info.value)


@pytest.mark.parametrize("name", FOUND)
def test_read_is_an_error_at_it(name: str) -> None:
    spec = parse_text(program(f"x + v*t + {name}*t^2;"), "eq.mxm")
    with pytest.raises(Max2CodeError) as info:
        maxima.program_script(spec.program.statements)
    assert str(info.value).startswith(f"eq.mxm:2:13: error: '{name}' is "), str(info.value)


@pytest.mark.parametrize("text", [
    "fpprec: 30$ x + v*t;",            # set, not read
    "x + v*float(t);",                 # called
    "e: x + v*t$ ev(e, numer);",       # an evaluation flag after a comma
    "'linel$ x + v*t;",                # quoted
    'printf(false, "fpprec expop")$ x + v*t; /* linel */',  # in a string, a comment
    "x + fpprecision*t + my_expop;",   # longer names
])
def test_uses_that_are_not_symbols_pass(text: str) -> None:
    spec = parse_text(program(text), "eq.mxm")
    assert "@@" in maxima.program_script(spec.program.statements)


def test_rename_is_token_wise() -> None:
    spec = parse_text(program('x: x + "x" + fx + f(x) + x(1) /* x */ + x;'), "eq.mxm")
    (stmt,) = maxima_names.rename(spec.program.statements, {"x": "o__p0"})
    assert stmt.text == 'o__p0: o__p0 + "x" + fx + f(o__p0) + x(1) /* x */ + o__p0;'


def test_name_length_limit() -> None:
    name = "p" * 256
    with pytest.raises(Max2CodeError) as info:
        parse_text(program(f"x + {name}*t;", f"x, {name}"), "eq.mxm")
    assert str(info.value) == "eq.mxm:1:15: error: a name of 256 characters; at most 255"
    parse_text(program(f"x + {'p' * 255}*t;", f"x, {'p' * 255}"), "eq.mxm")


def test_oracle_does_not_share_the_blind_spot(maxima_exe: str) -> None:
    """The oracle on an equation whose parameter is named fpprec and expop (the generator's
    check bypassed): the coefficients are the parameters' values, not 16 and nothing."""
    spec = parse_text(program("x + q*t + r*t^2;", "x, q, r"), "eq.mxm")
    stmts = tuple(dataclasses.replace(s, text=s.text.replace("r", "expop").replace("q", "fpprec"))
                  for s in spec.program.statements)
    spec = dataclasses.replace(spec, program=dataclasses.replace(spec.program, statements=stmts),
                               parameters=Declared(("x", "fpprec", "expop"), spec.parameters.pos))
    got = oracle.exact_coefficients(spec, ["x", "fpprec", "expop"], [[1.0, 2.5, 3.0]])
    assert got == [(Fraction(1), Fraction(5, 2), Fraction(3))]


def test_list_is_maxima_s_own(maxima_exe: str) -> None:
    """max2code/maxima/variables.txt is what the installed Maxima says (scripts/maxima-variables)."""
    proc = subprocess.run([str(ROOT / "scripts" / "maxima-variables"), "--check"],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert set(FOUND) <= set(maxima_names.variables())
