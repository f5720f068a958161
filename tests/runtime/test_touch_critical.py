"""The touch's interval settled in one pass: touch_critical certifies p convex around the
guess's touch, with one critical point there, and the pieces are scanned as the derivative
method scans them.

Once the guess (Laguerre, then Newton on p') reports a touch x and the Bernstein test clears
(0, lo], lo = x (1 - 2^-10), the interval (lo, hi] around it went to the derivative method:
p''' and a convexity test, the signs of p' at both ends, Newton on p', one after the other.
touch_critical bounds p''/2 from below on [lo, hi] by its Taylor expansion at x (Horner's
chains for p', p''/2, p'''/6 at x, bounds on the rounding and on p'''' at hi) and from that the
signs of p' at both ends; then the derivative method's own first Newton step on p' finds the
critical point, so the answers are the derivative method's, bit for bit.  Checked here:

* on grazes (exact double roots, degrees 4-8, with complex pairs and roots on both sides)
  C settles every default solve by the certificate: one Bernstein test, no Taylor point, no
  derivative-method call; Rust and Python take C's path (paths.assert_ports_take_c_path);
* where a complex pair sits inside (lo, hi] next to the touch (p'' changes sign there) the
  pure-Python certificate refuses (0), and C calls the derivative method;
* every runtime answers every call with the graze check (with and without a contact skin)
  right by the exact oracle (exact_roots.judge).
"""
from __future__ import annotations

from pathlib import Path
from typing import Sequence

import pytest

from . import cases
from . import paths
from .test_python_control_flow import counts_driver  # noqa: F401

Vector = tuple[tuple[float, ...], float]


def _vec(real: Sequence[str], pairs: Sequence[tuple[str, str]] = (), lead: str = "1") -> Vector:
    """Exact decimals multiplied out (cases.poly_from_roots), rounded once; tmax 10."""
    return cases.poly_from_roots(list(real), list(pairs), lead), 10.0


# a double root first: the guess's touch, certified
TOUCHES: list[Vector] = [
    _vec(["1", "1", "-2", "-5"]),                                   # degree 4
    _vec(["0.75", "0.75", "4", "6", "-1"]),                          # degree 5, roots beyond
    _vec(["1.5", "1.5", "-0.5"], [("3", "1")]),                      # rounding splits it
    _vec(["0.5", "0.5", "3", "-1", "-2", "-7"], [("-1", "1")]),      # degree 8
    _vec(["2", "2", "5", "-3"], [("1", "3"), ("-2", "0.5")], "-0.25"),
]
# a complex pair 0.003 past the touch at 1, inside (lo, hi]: p'' changes sign there, so the
# certificate must refuse and leave the interval to the derivative method
NEAR_PAIR: list[Vector] = [
    _vec(["1", "1", "-3"], [("1.003", "0.0001")]),
    _vec(["1", "1", "-3"], [("1.003", "0.0003")]),
]


def test_certificate_refuses_near_pair(monkeypatch: pytest.MonkeyPatch) -> None:
    got = paths.python_returns("touch_critical", TOUCHES + NEAR_PAIR, monkeypatch)
    for (c, tmax), calls in zip(TOUCHES, got):
        assert len(calls) == 1 and isinstance(calls[0], float) and calls[0] > 0, (c, calls)
    for (c, tmax), calls in zip(NEAR_PAIR, got[len(TOUCHES):]):
        assert calls == [0.0], (c, calls)


@pytest.mark.parametrize("runtime", ["c", "rust", "python", "python-c"])
def test_every_runtime_against_the_oracle(runtime: str, tmp_path: Path,
                                          monkeypatch: pytest.MonkeyPatch) -> None:
    # (the no-graze baseline does not look for touches, and never takes this path)
    vecs = TOUCHES + NEAR_PAIR
    rows = [r for r in paths.judged(runtime, vecs, tmp_path, monkeypatch) if r.method == "interval"]
    assert len(rows) == 2 * len(vecs)  # eps 0 and the skin
    bad = [str(r) for r in rows if not r.verdict.startswith("ok") or r.answer[0] != 1]
    assert not bad, f"{runtime}:\n" + "\n".join(bad)


def test_c_path(counts_driver: Path,  # noqa: F811 (the imported fixture)
                monkeypatch: pytest.MonkeyPatch) -> None:
    vecs = TOUCHES + NEAR_PAIR
    for i, ((c, tmax), row) in enumerate(zip(vecs, paths.c_solves(counts_driver, vecs))):
        # the test on (0, lo], then the certificate: no Taylor point, no derivative method
        # (near the pair: the derivative method)
        expected = (1, 0, 0, 1) if i < len(TOUCHES) else (1, 0, 1, 1)
        assert row.path == expected, (c, tmax, row)
    paths.assert_ports_take_c_path(counts_driver, vecs, monkeypatch)
