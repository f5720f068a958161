"""The Python runtime (runtime/python/max2code_runtime) against the shared hard cases and
random polynomials -- the same judge and the same bounds as the C runtime, except that Python
has no GSL method -- on both backends: the C runtime through cffi ("c", built by
`python -m max2code_runtime.build`; required under CI) and the pure-Python port ("python").
"""
from __future__ import annotations

import math
import os
import sys
from pathlib import Path

import pytest

from . import cases

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "runtime" / "python"))
import max2code_runtime as rt  # noqa: E402

RANDOM_COUNT = int(os.environ.get("M2C_RANDOM_CASES", "3000"))
ALL = cases.all_cases()
PY_METHODS = list(rt.METHODS)
C_BACKEND = rt._load_c()

Result = tuple[int, float, bool]


def _require_c_backend() -> None:
    """Skip without the cffi backend -- fail under CI, where scripts/setup builds it."""
    if C_BACKEND is None:
        why = "the cffi backend is not built (python -m max2code_runtime.build; needs cffi)"
        if os.environ.get("CI"):
            pytest.fail(why + " -- required in CI")
        pytest.skip(why)


@pytest.fixture(params=["c", "python"])
def backend(request: pytest.FixtureRequest, monkeypatch: pytest.MonkeyPatch) -> str:
    if request.param == "c":
        _require_c_backend()
        monkeypatch.setattr(rt, "_C", C_BACKEND)
    else:
        monkeypatch.setattr(rt, "_C", None)
    return request.param


def test_backend_in_use() -> None:
    """Importing picks the C backend when it is built, unless MAX2CODE_PURE_PYTHON is set."""
    assert rt.BACKEND == ("c" if C_BACKEND is not None and not os.environ.get("MAX2CODE_PURE_PYTHON")
                          else "python")
    if os.environ.get("CI"):
        assert C_BACKEND is not None, "scripts/setup builds the cffi backend"


@pytest.mark.parametrize("method", PY_METHODS)
@pytest.mark.parametrize("case", ALL, ids=[c.name for c in ALL])
def test_case(case: cases.Case, method: str, backend: str) -> None:
    st, t, g = rt.first_root_status(case.coeffs, case.tmax, method)
    why = cases.judge(case, method, st, t, g)
    assert why is None, f"{case.name} [{method}, {backend}]: {why}"


def test_first_root_contract(backend: str) -> None:
    assert rt.first_root(cases.KAHAN) == 1.0
    assert rt.first_root([1.0, 1.0]) is None  # root -1: none
    assert rt.first_root([-1.0, 1.0], tmax=0.5) is None
    assert rt.first_root([-1.0, 1.0], tmax=1.0) == 1.0
    # invalid input is not "no root" (issue 11): ValueError, and status -1
    for c, tmax, eps in (([1.0, math.nan], 1.0, 0.0), ([1.0, math.inf], 1.0, 0.0), ([1.0] * 18, 1.0, 0.0),
                         ([], 1.0, 0.0), (["x"], 1.0, 0.0), ([-1.0, 1.0], 0.0, 0.0),
                         ([-1.0, 1.0], math.nan, 0.0), ([-1.0, 1.0], 1.0, -1e-9), ([-1.0, 1.0], 1.0, math.nan)):
        with pytest.raises(ValueError, match="invalid input"):
            rt.first_root(c, tmax, eps)
        assert rt.first_root_status(c, tmax, eps=eps)[0] == -1
    assert rt.first_root_status([1.0] * 17, 1.0)[0] in (0, 1)  # degree 16 is valid
    assert rt.first_root_status([-1.0, 1.0], 1.0, method="gsl")[0] == -1  # no GSL in Python


def test_sequence_kinds(backend: str) -> None:
    """Any sized sequence of numbers is coefficients (the C backend unpacks it into the
    arguments of its binding for that many coefficients); something without a length is
    invalid input, on both backends."""
    import array

    c = cases.poly_from_roots(["0.5", "2", "-3"], [("1", "1")])
    want = rt.first_root_status(list(c), 10.0)
    assert want[0] == 1 and want[1] == pytest.approx(0.5, rel=1e-15)
    kinds: list = [tuple(c), array.array("d", c)]
    try:
        import numpy as np
        kinds += [np.array(c), np.array([c])[0]]
    except ImportError:
        pass
    for seq in kinds:
        assert rt.first_root_status(seq, 10.0) == want, type(seq)
    assert rt.first_root_status(range(0), 10.0)[0] == -1  # no coefficients
    assert rt.first_root_status((x for x in c), 10.0)[0] == -1  # no length


def test_bindings_by_length_are_the_array_call() -> None:
    """The C backend's binding for k coefficients (k double arguments, the common call) gives,
    bit for bit, what its array binding gives on the same coefficients, for every k from 1 to
    17: random polynomials, windows finite and infinite, and invalid input the C runtime
    reports (NaN, infinities, tmax <= 0).  Each takes exactly k + 1 arguments."""
    import random
    import struct

    _require_c_backend()
    bits = lambda v: struct.pack("<d", v)  # noqa: E731 - NaN == NaN by its bits
    rng = random.Random(20261203)
    roots = nones = 0
    for k in range(1, C_BACKEND.MAX_COEFFS + 1):
        by_len = C_BACKEND.BY_LEN[k]
        for i in range(300):
            c = [rng.uniform(-1, 1) * 10 ** rng.uniform(-3, 3) for _ in range(k)]
            tmax = (math.inf, 10 ** rng.uniform(-2, 2), 0.0, -1.0, math.nan)[i % 5 if i < 50 else i % 2]
            if i % 37 == 3:
                c[rng.randrange(k)] = rng.choice((math.nan, math.inf, -math.inf))
            want = C_BACKEND._packed(c, k - 1, tmax, 0, 0.0)
            got = by_len(*c, tmax)
            assert bits(got) == bits(want), (k, c, tmax, got, want)
            roots += got != 0 and not math.isnan(got)
            nones += got == 0
        with pytest.raises(TypeError):
            by_len(*([1.0] * (k + 1)), 1.0)  # one coefficient too many
    assert C_BACKEND.BY_LEN[0] is None
    assert roots > 1000 and nones > 1000  # both answers were compared, not only NaN


def test_extension_without_the_bindings_falls_back(monkeypatch: pytest.MonkeyPatch) -> None:
    """An extension module built from older sources (pip leaves the old one behind on an
    upgrade of an installed copy, where no stamp is checked) lacks the per-count bindings: the
    package then falls back to the pure-Python port instead of failing to import."""
    import types

    class OldLib:
        m2c_first_root_packed = staticmethod(lambda *a: 0.0)  # only what the old build had

    old = types.ModuleType("max2code_runtime._roots_c")
    old.ffi, old.lib = object(), OldLib()  # type: ignore[attr-defined]
    monkeypatch.setitem(sys.modules, "max2code_runtime._roots_c", old)
    monkeypatch.delitem(sys.modules, "max2code_runtime._cbackend", raising=False)
    monkeypatch.setattr(rt, "_cbackend", None, raising=False)
    monkeypatch.delenv("MAX2CODE_PURE_PYTHON", raising=False)
    monkeypatch.setattr("max2code_runtime._source.STAMP", Path("/nonexistent/stamp"))
    monkeypatch.setattr("max2code_runtime._source.source_digest", lambda src: "")
    with pytest.raises(ImportError, match="stale"):
        import max2code_runtime._cbackend  # noqa: F401
    assert rt._load_c() is None


def _first_root_or_error(c: object, tmax: float, eps: float = 0.0) -> object:
    try:
        return rt.first_root(c, tmax, eps)  # type: ignore[arg-type]
    except ValueError:
        return "invalid"


def test_first_root_is_first_root_status(backend: str) -> None:
    """first_root's straight call into C (lists and tuples, no skin) says what first_root_status
    says: the root of a crossing, the touch's time (not -t), None, and ValueError for invalid
    input -- on the shared cases (grazes among them), as a list and as a tuple, and on input
    that only the full path can report."""
    calls: list[tuple[object, float, float]] = []
    for case in ALL:
        for tmax in (case.tmax, math.inf):
            calls += [(list(case.coeffs), tmax, 0.0), (tuple(case.coeffs), tmax, 0.0)]
    calls += [([1.0, math.nan], 1.0, 0.0), ((1.0, math.inf), 1.0, 0.0), ([1.0] * 18, 1.0, 0.0),
              ([], 1.0, 0.0), ((), 1.0, 0.0), (["x"], 1.0, 0.0), ([None, 1.0], 1.0, 0.0),
              ([-1.0, 1.0], 0.0, 0.0), ([-1.0, 1.0], math.nan, 0.0), ([-1.0, 1.0], "2", 0.0),
              ([-1.0, 1.0], 1.0, math.nan), ([-1.0, 1.0], 2.0, 1e-3), ([-1, 1], 2, 0),
              ([1e308, -1e308, 1e308], 10.0, 0.0)]
    touches = 0
    for c, tmax, eps in calls:
        st, t, g = rt.first_root_status(c, tmax, eps=eps)  # type: ignore[arg-type]
        want = "invalid" if st == -1 else t if st == 1 else None
        got = _first_root_or_error(c, tmax, eps)
        assert got == want, (c, tmax, eps, got, want)
        touches += st == 1 and g
    assert touches > 0  # the touches' sign was read back


def test_graze_flag_and_nograze(backend: str) -> None:
    """A touch is reported flagged; without the check it is skipped."""
    c = cases.poly_from_roots(["1", "1", "5"], [("0", "1")])
    c = (c[0] * (1 + 2.0**-52),) + c[1:]  # no exact zero at the touch
    st, t, g = rt.first_root_status(c)
    assert st == 1 and g and abs(t - 1) < 1e-7
    st, t, g = rt.first_root_status(c, method="interval-nograze")
    assert st == 1 and abs(t - 5) < 1e-12 and not g


def test_contact_skin(backend: str) -> None:
    """((t-1)^2 + d)(3 - t): a pass at d above zero at t = 1, then a crossing at 3.  Without a
    skin the crossing is the answer; a skin above d makes the pass a touch at t = 1 (the time of
    closest approach); a skin below d changes nothing."""
    d = 1e-9
    c = [3.0 * (1.0 + d), -(7.0 + d), 5.0, -1.0]
    assert rt.first_root(c) == pytest.approx(3.0, rel=1e-15)
    st, t, g = rt.first_root_status(c, eps=1e-8)
    assert st == 1 and g and abs(t - 1) < 1e-6
    assert rt.first_root(c, eps=1e-10) == rt.first_root(c)
    # scaled coefficients: the skin is in the units of c
    big = [x * 1e6 for x in c]
    assert rt.first_root(big, eps=1e-8) == pytest.approx(3.0, rel=1e-15)
    assert rt.first_root(big, eps=1e-2) == pytest.approx(1.0, rel=1e-6)
    # the quadratic's vertex
    assert rt.first_root([1.0 + d, -2.0, 1.0]) is None
    assert rt.first_root([1.0 + d, -2.0, 1.0], eps=2e-9) == 1.0


def test_python_matches_c_algorithm_on_kahan_discriminant() -> None:
    """The corrected discriminant of Kahan's quadratic is exactly h^2 - a c = 1 (scaled)."""
    from max2code_runtime.solver import quad_roots

    roots, disc = quad_roots(94906266.375, -2 * 94906267.375, 94906268.375)
    assert roots is not None and roots[0] == 1.0
    assert roots[1] == pytest.approx(1.0000000210734243, rel=4e-16)
    assert disc > 0


def test_fma_emulation_is_correctly_rounded() -> None:
    """The pure-Python fma (exact rationals, one rounding) against cases where a*b + c
    rounded twice is wrong."""
    from max2code_runtime.solver import fma_exact

    a = 1.0 + 2.0**-30
    assert fma_exact(a, a, -1.0) == 2.0**-29 + 2.0**-60  # a*a rounds the 2^-60 away
    assert fma_exact(2.0**1023, 2.0, -(2.0**1023)) == 2.0**1023  # a*b alone overflows
    assert fma_exact(1e308, 10.0, -1e308) == math.inf
    assert fma_exact(1e308, 10.0, 0.0) == math.inf
    assert fma_exact(2.0**-1074, 0.5, 0.0) == 0.0  # ties to even
    assert fma_exact(2.0**-1074, 1.5, 0.0) == 2.0**-1073


def test_first_roots_batch(backend: str) -> None:
    np = pytest.importorskip("numpy")
    rows = [[-6.0, 11.0, -6.0, 1.0], [1.0, 1.0, 1.0, 1.0], [math.nan, 1.0, 0.0, 0.0], [2.0, -3.0, 1.0, 0.0]]
    got = rt.first_roots(np.array(rows), math.inf)
    assert isinstance(got, np.ndarray) and got.shape == (4,)
    assert got[0] == 1.0 and math.isnan(got[1]) and math.isnan(got[2]) and got[3] == 1.0
    rc = cases.random_cases(200)
    by_degree: dict[int, list] = {}
    for r in rc:
        by_degree.setdefault(len(r.coeffs), []).append(r.coeffs)
    for width, group in by_degree.items():
        batch = rt.first_roots(np.array(group), 10.0)
        single = [rt.first_root(c, 10.0) for c in group]
        assert [None if math.isnan(x) else x for x in batch] == single
    assert rt.first_roots(np.zeros((0, 3))).shape == (0,)
    with pytest.raises(ValueError):
        rt.first_roots(np.zeros((2, 18)))
    with pytest.raises(ValueError):
        rt.first_roots(np.zeros(5))


def test_first_roots_without_numpy(backend: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """numpy is optional for the runtime: a list of lists gives a list."""
    monkeypatch.setitem(sys.modules, "numpy", None)  # import numpy -> ImportError
    got = rt.first_roots([[-6.0, 11.0, -6.0, 1.0], [1.0, 1.0, 1.0, 1.0]], 5.0)
    assert isinstance(got, list) and got[0] == 1.0 and math.isnan(got[1])
    with pytest.raises(ValueError):
        rt.first_roots([[1.0, 2.0], [1.0]])


def test_input_no_float_can_hold_is_invalid(backend: str) -> None:
    """An int too large for a float (coefficient, tmax or eps) is invalid input: status -1
    from first_root_status, which never raises, and ValueError from first_root, on either
    backend and through every branch (the C call without a skin, the others)."""
    huge = 10**400
    for c, tmax, eps in (([huge, -1.0], 1.0, 0.0), ([1.0, -1.0], huge, 0.0),
                         ([huge, -1.0], 1.0, 1e-3), ([1.0, -1.0], 2.0, huge)):
        for method in ("interval", "closed") if eps == 0.0 else ("interval",):
            st, t, g = rt.first_root_status(c, tmax, method, eps)
            assert st == -1 and math.isnan(t) and not g, (c, tmax, eps, method)
        with pytest.raises(ValueError):
            rt.first_root(c, tmax, eps)


def test_skin_only_with_the_interval_method(backend: str) -> None:
    """The skin widens the graze check, which only "interval" has: eps > 0 with another method
    is invalid input on both backends (the C binding's rule), never a skin that one degree
    honours and another ignores."""
    d = 1e-9
    c = [3.0 * (1.0 + d), -(7.0 + d), 5.0, -1.0]  # a pass at d above zero at 1, a root at 3
    assert rt.first_root_status(c, 5.0, "interval", 1e-8)[:1] == (1,)
    for method in ("closed", "interval-nograze"):
        for coeffs in (c[:3], c, c + [0.0, 1e-3]):  # degrees 2, 3 and 5
            st, t, _ = rt.first_root_status(coeffs, 5.0, method, 1e-8)
            assert st == -1 and math.isnan(t), (method, coeffs)
        assert rt.first_root_status(c, 5.0, method, 0.0)[0] == 1


@pytest.mark.parametrize("numpy_present", [True, False])
def test_first_roots_scalars_as_first_root_status(backend: str, numpy_present: bool,
                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    """tmax and eps that first_root_status refuses (a string, None, an int no float holds)
    make every row NaN on both backends, with numpy or without it; a row holding something
    other than numbers is NaN without numpy (numpy converts what it can itself)."""
    if not numpy_present:
        monkeypatch.setitem(sys.modules, "numpy", None)
    rows = [[-6.0, 11.0, -6.0, 1.0], [2.0, -3.0, 1.0, 0.0]]
    for tmax, eps in (("5", 0.0), (None, 0.0), (5.0, "0"), (10**400, 0.0), (5.0, None)):
        got = list(rt.first_roots(rows, tmax, eps))
        assert len(got) == 2 and all(math.isnan(x) for x in got), (tmax, eps, got)
    assert list(rt.first_roots(rows, 5.0)) == [1.0, 1.0]
    # a row holding None or an int no float holds: NaN for that row, numpy or not
    got = list(rt.first_roots([[-6.0, 11.0, -6.0, 1.0], [None, 1.0, 1.0, 1.0],
                               [10**400, 1.0, 1.0, 1.0]], 5.0))
    assert got[0] == 1.0 and math.isnan(got[1]) and math.isnan(got[2]), got
    if not numpy_present:
        got = rt.first_roots([[-6.0, 11.0, -6.0, 1.0], [None, 1.0, 1.0, 1.0],
                              ["1", -3.0, 1.0, 0.0]], 5.0)
        assert got[0] == 1.0 and math.isnan(got[1]) and math.isnan(got[2])
        with pytest.raises(ValueError):
            rt.first_roots([1.0, 2.0, 3.0])  # one row, not rows
    assert len(rt.first_roots([], 5.0)) == 0


def test_batches_go_to_c_in_chunks(monkeypatch: pytest.MonkeyPatch) -> None:
    """m2c_first_roots counts rows in a C int: the binding splits larger batches.  With the
    chunk made 2 rows, 5 rows (numpy and lists) give the single calls' answers."""
    _require_c_backend()
    np = pytest.importorskip("numpy")
    monkeypatch.setattr(rt, "_C", C_BACKEND)
    monkeypatch.setattr(C_BACKEND, "CHUNK", 2)
    rows = [[-6.0, 11.0, -6.0, 1.0], [1.0, 1.0, 1.0, 1.0], [-0.5, 1.0, 0.0, 0.0],
            [2.0, -3.0, 1.0, 0.0], [-24.0, 50.0, -35.0, 10.0]]
    single = [rt.first_root(r, 10.0) for r in rows]
    assert all(x is not None for i, x in enumerate(single) if i != 1)
    want = [math.nan if x is None else x for x in single]
    for got in (rt.first_roots(np.array(rows), 10.0), C_BACKEND.solve_batch(rows, 10.0, 0.0)):
        assert [repr(float(x)) for x in got] == [repr(x) for x in want]


# Same kappa-relative bounds as for C (see test_c_runtime.random_bound).
def test_random(backend: str) -> None:
    count = RANDOM_COUNT if backend == "c" else RANDOM_COUNT // 3
    results = [(case, method, rt.first_root_status(case.coeffs, case.tmax, method))
               for case in cases.random_cases(count) for method in PY_METHODS]
    bad = list(cases.random_failures(results))
    assert not bad, f"{len(bad)} failures, first: " + "\n".join(bad[:10])


def test_report_worst_errors(capsys: pytest.CaptureFixture[str]) -> None:
    """Prints the worst relative error per family and method (run with -s)."""
    results = {(c.name, m): rt.first_root_status(c.coeffs, c.tmax, m) for c in ALL for m in PY_METHODS}
    table = cases.format_worst(cases.worst_errors(results), "Python runtime: worst relative error")
    with capsys.disabled():
        print("\n" + table)
