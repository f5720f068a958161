"""The runtimes' own fuzz against the exact oracle (issue 33): infinite windows, constant terms
within an ulp of 0, clustered roots -- in every runtime (C, Modula-2 through gm2, Rust, Python
on both backends).

Three classes of vectors, drawn by hypothesis (derandomized: the same vectors in every run):

* ``infinite``: polynomials built from exact roots (positive, negative, complex pairs, of any
  magnitude from 1e-6 to 1e6), rounded once, tmax = inf;
* ``ulp``: throws (c_0 + v t + a t^2, maybe a cubic term) and the polynomials above, with a
  constant term within a few ulps of 0 (a body an ulp from a boundary: the smallest
  subnormal, an ulp of the other terms' scale, 1e-16), tmax = inf or finite;
* ``cluster``: two to five roots within 1e-3..1e-16 relative of each other (a triple root
  plus a small perturbation among them), next to roots 1e6-1e12 times larger or smaller (huge
  scale separation), an optional ulp nudge of c_0, any window.

Every answer is judged by exact_roots.judge (integer arithmetic on the doubles themselves:
nothing of the runtimes' code): no miss, no false root, the first root within the documented
tolerance.  WINDOW_FUZZ_COUNT sets the vectors per class and runtime (300 by default, as in
CI; the pure-Python port gets a third of them, being ~100 times slower); e.g.
WINDOW_FUZZ_COUNT=30000 for a long run.

test_never_later_than_the_exact_first_root (item 11) asks more of the cluster class: no answer
later than the exact first root of the double coefficients by more than 8 ulps.  Inside the
rounding band of a cluster the polish may settle on a later root of the cluster (the judge's
tolerance, 64 n u kappa, would excuse it: kappa is huge there); the runtimes' never_late
answers the earliest point it cannot exclude instead (docs/runtimes.md).
"""
from __future__ import annotations

import math
import os
from collections import Counter
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from . import every_runtime as er
from . import exact_roots as ex
from . import paths
from . import test_fuzz_runtimes as tf
from . import test_m2_runtime as m2

drivers = m2.drivers  # (the Modula-2 driver, for "m2")

COUNT = int(os.environ.get("WINDOW_FUZZ_COUNT", "300"))
BATCH = 50
U = 2.0**-53
LATE_ULPS = 8

TALLY: Counter = Counter()  # (class, runtime, "tried" | "held") -> count, for the summary


def _mag(lo: float, hi: float) -> st.SearchStrategy[Fraction]:
    """10^x for x uniform in [lo, hi], as an exact rational of the double."""
    return st.floats(lo, hi).map(lambda x: Fraction(10.0**x))


signs = st.sampled_from((1, -1))
reals = st.tuples(_mag(-6, 6), signs).map(lambda m: m[0] * m[1])
pairs = st.tuples(_mag(-6, 6), st.floats(-1, 1), st.floats(0.01, 1))


def _from_roots(roots: list[Fraction], cpairs: list[tuple[Fraction, float, float]],
                lead: Fraction) -> tuple[float, ...]:
    """lead * prod (t - r) * prod of the complex pairs' quadratics, exact, rounded once."""
    c = [Fraction(1)]

    def times(f: list[Fraction]) -> None:
        nonlocal c
        out = [Fraction(0)] * (len(c) + len(f) - 1)
        for i, a in enumerate(c):
            for j, b in enumerate(f):
                out[i + j] += a * b
        c = out
    for r in roots:
        times([-r, Fraction(1)])
    for m, re, im in cpairs:
        x, y = m * Fraction(re), m * Fraction(im)
        times([x * x + y * y, -2 * x, Fraction(1)])
    return tuple(float(v * lead) for v in c)


@st.composite
def infinite(draw: st.DrawFn) -> er.Vector:
    roots = draw(st.lists(reals, min_size=1, max_size=6))
    cp = draw(st.lists(pairs, max_size=(8 - len(roots)) // 2))
    return _from_roots(roots, cp, draw(st.tuples(_mag(-3, 3), signs)).__getitem__(0)), math.inf


def _ulp_constant(draw: st.DrawFn, scale: float) -> float:
    tiny = draw(st.sampled_from(("subnormal", "ulp", "ulp2", "1e-16", "zero-ish")))
    value = {"subnormal": 5e-324, "ulp": math.ulp(scale) * draw(st.integers(1, 4)),
             "ulp2": math.ulp(math.ulp(scale)), "1e-16": 1e-16,
             "zero-ish": scale * 2.0 ** -draw(st.integers(45, 60))}[tiny]
    return value * draw(signs)


@st.composite
def ulp(draw: st.DrawFn) -> er.Vector:
    """Half of them a throw (c_0 + v t + a t^2, sometimes a small cubic term: a body an ulp
    from a boundary under gravity, the engine's cell-crossing polynomial), half a polynomial
    of infinite()'s with its c_0 so replaced."""
    if draw(st.booleans()):
        c = [0.0, float(draw(reals)), float(draw(reals))]
        if draw(st.booleans()):
            c.append(float(draw(reals)) * 1e-3)
    else:
        c = list(draw(infinite())[0])
    c[0] = _ulp_constant(draw, max(abs(x) for x in c[1:]))
    tmax = draw(st.sampled_from((math.inf, math.inf, 1.0, 1e3, 1e-3)))
    return tuple(c), tmax


@st.composite
def cluster(draw: st.DrawFn) -> er.Vector:
    a = draw(_mag(-2, 2))
    k = draw(st.integers(2, 5))
    deltas = draw(st.lists(st.tuples(st.floats(3, 16), st.sampled_from((0, 1, -1))),
                           min_size=k, max_size=k))
    roots = [a * (1 + s * Fraction(10.0**-d)) for d, s in deltas]
    far = draw(st.lists(st.tuples(st.floats(6, 12), signs, st.sampled_from((1, -1))),
                        max_size=2))  # huge scale separation
    roots += [a * Fraction(10.0 ** (e * d)) * s for d, s, e in far]
    roots += draw(st.lists(reals, max_size=max(0, 7 - len(roots))))
    c = list(_from_roots(roots, [], draw(st.tuples(_mag(-3, 3), signs)).__getitem__(0)))
    if draw(st.booleans()):
        c[0] += math.ulp(c[0]) * draw(st.integers(-4, 4))
    tmax = draw(st.sampled_from((math.inf, float(a) * 2, float(a) * 1.0001, 1e3)))
    return tuple(c), tmax


CLASSES = {"infinite": infinite(), "ulp": ulp(), "cluster": cluster()}


@pytest.fixture(scope="module")
def c_exe(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tf.build_driver(tmp_path_factory.mktemp("hostile") / "roots_driver")


def _examples(runtime: str) -> int:
    share = 3 if runtime == "python" else 1
    return max(1, COUNT // BATCH // share)


def _run(runtime: str, vecs: list[er.Vector], tmp: Path, request: pytest.FixtureRequest
         ) -> list[er.Answer]:
    m2_exe = request.getfixturevalue("drivers")[0] if runtime == "m2" else None
    c_exe = request.getfixturevalue("c_exe") if runtime == "c" else None
    with pytest.MonkeyPatch.context() as mp:
        return er.answers(runtime, vecs, tmp, mp, m2_exe, c_exe)


def _late(c: tuple[float, ...], tmax: float, answer: er.Answer) -> bool:
    """A root later than the exact first root by more than LATE_ULPS ulps (and by more than
    the least subnormal: a subnormal root has fewer bits, as exact_roots.judge allows)."""
    st_, t, _ = answer
    if st_ != 1:
        return False
    truth = ex.first_root(c, tmax)
    return truth.kind != "none" and (
        Fraction(t) > truth.hi * (1 + Fraction(LATE_ULPS * U)) + Fraction(ex.TRUE_MIN))


def _wrong_or_late(vecs: list[er.Vector], got: list[er.Answer], eps: float = 0.0) -> list[str]:
    """The answers the exact judge refuses (eps: the contact skin given) or _late finds late,
    each with its vector."""
    out = []
    for (c, t), a in zip(vecs, got):
        verdict = ex.judge(c, t, *a, eps=eps)
        if not verdict.startswith("ok") or _late(c, t, a):
            out.append(f"{verdict}, late {_late(c, t, a)}: {a} for c={c!r}, tmax={t!r}")
    return out


@pytest.mark.parametrize("runtime", er.RUNTIMES)
@pytest.mark.parametrize("kind", list(CLASSES))
def test_against_the_exact_oracle(kind: str, runtime: str, tmp_path_factory: pytest.TempPathFactory,
                                  request: pytest.FixtureRequest) -> None:
    tmp = tmp_path_factory.mktemp(f"{kind}-{runtime}")

    @settings(max_examples=_examples(runtime), deadline=None, derandomize=True, database=None,
              suppress_health_check=list(HealthCheck))
    @given(st.lists(CLASSES[kind], min_size=BATCH, max_size=BATCH))
    def batch(vecs: list[er.Vector]) -> None:
        got = _run(runtime, vecs, tmp, request)
        bad = [f"{ex.judge(c, t, *a)}: {a} for c={c!r}, tmax={t!r}" for (c, t), a in zip(vecs, got)
               if not ex.judge(c, t, *a).startswith("ok")]
        TALLY[kind, runtime, "tried"] += len(vecs)
        TALLY[kind, runtime, "held"] += len(vecs) - len(bad)
        assert not bad, f"{len(bad)} of {len(vecs)}:\n" + "\n".join(bad[:6])
    batch()
    print(f"\n{kind} {runtime}: {TALLY[kind, runtime, 'held']} of "
          f"{TALLY[kind, runtime, 'tried']} held")


# Drawn by the cluster class in a full run (CI, 2026-12-06): complex roots 0.9995 +- 3.5e-4 i and
# 1.0002 +- 5.7e-4 i, the first real root at 1.0006.  At tmax = 1.0001 p is 2.4e-18 of its size,
# the fma sign at the window's end was noise, and every runtime reported a crossing at tmax where
# p is certainly of one sign (compensated Horner: error ~1e-30 of the size).
NOISE_AT_THE_END = (-11724.81643759225, -800985643.1160833, 4005106393.3789363, -8010334640.401654,
                    8010397858.715328, -4005218799.6389837, 801046550.255481, 5.623413251903491)


@pytest.mark.parametrize("runtime", er.RUNTIMES)
def test_no_crossing_from_the_noise_at_the_window_end(runtime: str, tmp_path: Path,
                                                      request: pytest.FixtureRequest) -> None:
    vecs = [(NOISE_AT_THE_END, t) for t in (1.0001, 1.0005, 1.0002, 1.00001, 1.00059, math.inf)]
    got = _run(runtime, vecs, tmp_path, request)
    bad = [f"{ex.judge(c, t, *a)}: {a} for tmax={t!r}" for (c, t), a in zip(vecs, got)
           if not ex.judge(c, t, *a).startswith("ok")]
    assert not bad, "\n".join(bad)


# Clusters inside the fma noise (WINDOW_FUZZ_COUNT=20000, cluster class and item 11's test): the
# scan saw a near-miss touch where p is certainly positive (compensated) -- at 1 + 9.1e-5 and
# 1 + 7.6e-6 -- while the exact polynomial of the doubles has its first root at 1 (a quintic
# cluster) and at 1 - 5.3e-8 (a quartic one).  Now solved again inside the noise, after a
# double-double shift (docs/runtimes.md).  The third: a crossing the derivative method's scan
# found at 1 + 1.7e-4 by fma signs, with the quintic cluster's first two roots (at 1 - 1.7e-4,
# the exact first, and near 1) inside the noise to its left; never_late took it to the edge
# of its band (a touch at 1.0001726794909491).  Now a scanned crossing is looked for again
# inside the noise too.
INSIDE_THE_NOISE = [
    ((-0.07951226132556138, 0.397481868769649, -0.7948048618280069, 0.7946459861217404,
      -0.3972435552102493, 0.07943282347242814), math.inf),
    ((0.007883173239276923, -0.03153269330775821, 0.04729904048761308, -0.03153269400905923,
      0.007883173589927435), 2.0),
    ((-1.000000124361768, 5.000000497447069, -10.000000746170599, 10.000000497447063,
      -5.000000124361765, 1.0), 1000.0),
    # drawn by the default-count never_later test in tests/runtime's order (2026-12-07): the
    # second solve's crossing, 0.99988437111925, was 2.1e-13 later than the exact first root
    # 0.9998843711190396: the shift's coefficients, rounded once, move the cluster's roots by
    # that much.  Now the second solve's root is held to p's own compensated band as
    # never_late holds a root (0.99988437111892936, 1.1e-13 early).
    ((-0.0012138810749942042, 0.006069405374970908, -0.012138810749941588, 0.012138810749941357,
      -0.006069405374970563, 0.0012138810749940897), 1000.0)]


@pytest.mark.parametrize("runtime", er.RUNTIMES)
def test_a_cluster_inside_the_fma_noise_is_not_late(runtime: str, tmp_path: Path,
                                                    request: pytest.FixtureRequest) -> None:
    bad = _wrong_or_late(INSIDE_THE_NOISE, _run(runtime, INSIDE_THE_NOISE, tmp_path, request))
    assert not bad, "\n".join(bad)


def test_never_later_than_the_exact_first_root(c_exe: Path, tmp_path: Path) -> None:
    """Item 11 on the C runtime (the others give its bits: test_fuzz_runtimes): two vectors of
    a probe's family (a cluster of the kind cluster() draws: the first answered 3.4e-4
    relative late, the second 8e-9, as a touch), two of cluster()'s that were late as
    touches, then hypothesis' clusters."""
    late: list[str] = []
    known = [((-4526.265110260407, -42727.67068683713, -43243.986313008056, 8486.923451889525,
               -128.9677850737716, -70.65389590902764, 6.269276635973642, -0.2119931648724115,
               0.0026213544068177425), math.inf),
             ((-0.002419247692347698, 0.11568422999746697, -1.3819507078372428,
               -0.024011912462834347), 0.08361970241593972),
             # touches reported inside the band after a crossing (1.2e-4 and 1e-8 late)
             ((-3.672911555825168e+16, -3.273982845668814e+19, 4.4853203804724896e+19,
               -2.302840884981096e+19, 5.253905943544464e+18, -4.494728355956265e+17,
               -153319395885.92047, 163.17136555397104), 2.922824995152161),
             ((2.0541031863583015e+20, -1.6292853547313964e+21, 3.2308147721405014e+21,
               -254362408655.78323, 4.836523629394905), 1000.0)]
    with pytest.MonkeyPatch.context() as mp:
        got = er.answers("c", known, tmp_path, mp, c_exe=c_exe)
    late.extend(f"{a} for c={c!r}, tmax={t!r}" for (c, t), a in zip(known, got) if _late(c, t, a))

    @settings(max_examples=max(1, COUNT // BATCH), deadline=None, derandomize=True,
              database=None, suppress_health_check=list(HealthCheck))
    @given(st.lists(cluster(), min_size=BATCH, max_size=BATCH))
    def batch(vecs: list[er.Vector]) -> None:
        with pytest.MonkeyPatch.context() as mp:
            got = er.answers("c", vecs, tmp_path, mp, c_exe=c_exe)
        late.extend(f"{a} for c={c!r}, tmax={t!r}" for (c, t), a in zip(vecs, got) if _late(c, t, a))
    batch()
    print(f"\nlater than the exact first root by > {LATE_ULPS} ulps: {len(late)}")
    assert not late, f"{len(late)} late:\n" + "\n".join(late[:6])


# Item 11 on the paths never_late did not take (a helper's seeded probes, 2026-12-07; the C
# runtime's answers before): a linear or quadratic rest once reduce dropped negligible leading
# terms (the closed form's root of the rest, up to 7.2e-8 relative late: a dropped term moves a
# near-double root by far more than its own size), and coefficients spanning more than 2^1021
# (the sliced path, never_late not called at all: up to 6.9e-4 late).
NOT_LOOKED_AT = [
    # linear rest: 4.6e-15 and 4.1e-15 late (0.009605604424220886, 0.006303131047945968)
    ((139.49756328401585, -14522.518013782412, -1.2668063281064114e-09, -2.0299460759817435e-07,
      -4.154780690517971e-05), 0.009701660468463096),
    ((0.0231890193922312, -3.6789683120721275, -4.68066852215877e-13, -1.469159135571602e-10,
      -2.566133650841086e-08), 0.006366162358425428),
    # quadratic rest: 7.2e-8 and 2.1e-8 late (8.173214379164966, 43.09077210507359)
    ((5746.968532470706, -1406.293343653107, 86.03061584682152, -2.214792773940417e-14,
      -3.870126174646632e-15, -5.093503045054985e-16, -5.534858091400858e-17,
      1.1505024744542578e-17), 8.174031762667177),
    ((37.67452610354025, -1.7486122208374744, 0.02028986834803768, -6.071108945737426e-19),
     43.09508203952099),
    # sliced: 6.9e-4 and 5.7e-4 late (40.51962313561369, 7.515761555251422)
    ((1.196773918867459e-299, 4395660204.6637335, -33449714.477453537, -36026736.05691751,
      2438734.2353931717, -68333.90392132907, 903.5128000765648, -4.657910566431389),
     40.52480192885757),
    ((-3.846514871759853e-306, -25729.574196252153, 17116.182167662348, -4554.505096151595,
      605.9621376915945, -40.31064896886715, 1.0726402322636537), 1000.0),
    # sliced after reduce dropped leading terms, which the slices ignored (drawn by
    # test_never_later_on_the_other_paths at WINDOW_FUZZ_COUNT=20000, then seeded probes: 167
    # of 517 such answers late): 1.1e-12, 3.0e-8 and 1.8e-6 late (0.029721559942624976,
    # 0.013614981051823342, 14.646450050734863)
    ((-3.3258577414366687e-308, -15586.445676583126, 957939.3699285828, -11533122.761897592,
      -103157020.54069194, 11604521.225111848, 102199080.17076336, -55812.017537672706, 1.0),
     0.02975428638497227),
    ((-8.3643e-318, -0.02243474402174909, 3.2540265511952415, -114.92842483283557,
      -223.28264501708705, -35.83132715367612, 4.813837952416593e-08), 0.013616342543350845),
    ((1.641495927737793e-303, 213174.6975584243, -43662.08372855728, 2980.9315638802727,
      -67.83882201149895, -2.613564326338746e-14, -4.502075622300545e-16), 14.648416140280153)]

# ... and with a contact skin (eps = 1e-9 here), where none of never_late ran: the derivative
# method's crossings inside a cluster's noise, 4.2e-3, 3.4e-3 and 6.7e-4 late.
SKIN = 1e-9
SKIN_CLUSTERS = [
    ((-2.7167356488905e-07, 9.21552881792568e-06, -0.00013025124950432333, 0.0009818434815270576,
      -0.0041631796245135124, 0.009414706029137028, -0.008871093059031212), 1000.0),
    ((-1.9782847542819018, 28.02399526807716, -165.40935037741275, 520.7014521711613,
      -922.019377371852, 870.7430880272008, -342.63267839897173), math.inf),
    ((-1301288374169.8943, 7513351379755.501, -17355627289680.492, 20053478141653.652,
      -11596856168470.506, 2693195012890.972, -6139165213.905673, 0.019422396128426042),
     1.732667436307536)]


@pytest.mark.parametrize("runtime", er.RUNTIMES)
def test_never_late_after_dropped_terms_and_on_slices(runtime: str, tmp_path: Path,
                                                      request: pytest.FixtureRequest) -> None:
    bad = _wrong_or_late(NOT_LOOKED_AT, _run(runtime, NOT_LOOKED_AT, tmp_path, request))
    assert not bad, "\n".join(bad)


@pytest.mark.parametrize("runtime", [r for r in er.RUNTIMES if r != "m2"])  # (no skin in m2's driver)
def test_never_late_with_a_contact_skin(runtime: str, tmp_path: Path,
                                        monkeypatch: pytest.MonkeyPatch) -> None:
    got = paths.answers(runtime, SKIN_CLUSTERS, tmp_path, monkeypatch,
                        calls=(("interval", 0, SKIN, f"skin:{SKIN!r}"),))
    bad = _wrong_or_late(SKIN_CLUSTERS, got, SKIN)
    assert not bad, "\n".join(bad)


@st.composite
def other_paths(draw: st.DrawFn) -> tuple[er.Vector, float]:
    """(vector, contact skin) on item 11's other paths, a third each: a rest of degree 1 to 3
    (roots clustered as cluster() draws them) under one to three leading terms negligible over
    the window, which step 3 drops; a cluster beside a root 1e300-1e306 times larger or
    1e309-1e318 times smaller, so that the coefficients span more than 2^1021 (the sliced
    path); a cluster of cluster() with a skin 1e-14..1e-6 of its largest coefficient."""
    kind = draw(st.sampled_from(("dropped", "sliced", "skin")))
    if kind == "skin":
        c, tmax = draw(cluster())
        return (c, tmax), max(abs(x) for x in c) * 10.0 ** -draw(st.floats(6, 14))
    a = draw(_mag(-2, 2))
    k = draw(st.integers(1, 3) if kind == "dropped" else st.integers(2, 5))
    roots = [a * (1 + s * Fraction(10.0**-d)) for d, s in draw(st.lists(
        st.tuples(st.floats(3, 16), st.sampled_from((0, 1, -1))), min_size=k, max_size=k))]
    lead = draw(st.tuples(_mag(-3, 3), signs))
    if kind == "sliced":
        far = draw(st.one_of(st.floats(300, 306).map(lambda d: Fraction(10.0**d)),
                             st.floats(309, 318).map(lambda d: -Fraction(10.0**-d))))
        roots += draw(st.lists(reals, max_size=7 - len(roots)))
        try:  # (no assume(): it would reject the whole batch)
            c = list(_from_roots(roots + [a * far], [], lead[0] * lead[1]))
        except OverflowError:
            c = list(_from_roots(roots, [], lead[0] * lead[1]))
        tmax = draw(st.sampled_from((math.inf, float(a) * 2, float(a) * 1.0001, 1e3)))
        return (tuple(c), tmax), 0.0
    c = list(_from_roots(roots, [], lead[0] * lead[1]))
    tmax = float(a) * draw(st.sampled_from((1.0000001, 1.0001, 2.0, 8.0)))
    for _ in range(draw(st.integers(1, 3))):  # |c_m| T^(m-i) below 4 m eps |c_i|: dropped
        m = len(c)
        room = max(abs(v) / tmax ** (m - i) for i, v in enumerate(c)) * 4 * (m - 1) * 2.0**-52
        c.append(room * draw(st.floats(0.01, 1)) * draw(signs))
    return (tuple(c), tmax), 0.0


def test_never_later_on_the_other_paths(c_exe: Path) -> None:
    """Item 11 where never_late came late (a linear or quadratic rest after dropped terms,
    extreme spreads, a contact skin): hypothesis' vectors of other_paths on the C runtime."""
    late: list[str] = []
    tried: Counter = Counter()

    @settings(max_examples=max(1, COUNT // BATCH), deadline=None, derandomize=True,
              database=None, suppress_health_check=list(HealthCheck))
    @given(st.lists(other_paths(), min_size=BATCH, max_size=BATCH))
    def batch(drawn: list[tuple[er.Vector, float]]) -> None:
        lines = [tf.c_line(f"0:{eps!r}" if eps else 0, c, t) for (c, t), eps in drawn]
        for ((c, t), eps), (st_, r, g, _) in zip(drawn, tf.run_timed(c_exe, lines)):
            exps = [math.frexp(x)[1] for x in c if x != 0]
            tried["skin" if eps else "sliced" if max(exps) - min(exps) > 1021 else
                  "dropped" if ex.documented_reduction(c, t) != c else "neither"] += 1
            if _late(c, t, (st_, r, g)):
                late.append(f"{(st_, r, g)} for c={c!r}, tmax={t!r}, eps={eps!r}")
    batch()
    print(f"\nother paths {dict(tried)}: later than the exact first root by > {LATE_ULPS} "
          f"ulps: {len(late)}")
    assert not late, f"{len(late)} late:\n" + "\n".join(late[:6])


# A touch inside the rounding band: the doubles of this cubic (a triple root at 1, rounded; drawn
# by test_never_later_on_the_other_paths at WINDOW_FUZZ_COUNT=20000 with a negligible t^4 term,
# which step 3 drops) have roots at 1 - 1.3e-15 and exactly 1, p(1) = 0, compensated Horner's band
# about |t - 1| < 2e-10 around them. While a touch inside the band stood, every runtime answered
# the touch 1.0, 12 u after the exact first root. Now a touch stands only where p is certainly
# positive just before it (or at it: a near miss); this one is walked to the band's left edge,
# the earliest point that cannot be excluded (item 11): 1 - 1.9e-10, a touch.
IN_BAND_TOUCH = [((-1.7684076812891022e+303, 5.305223043867309e+303, -5.3052230438673115e+303,
                   1.7684076812891046e+303), 1.0001)]


# A crossing once missed on the sliced path (coefficients spanning more than 2^1021): drawn by
# test_never_later_on_the_other_paths in a full `make test` (its draws depend on the modules loaded
# before it) after the fixes of 273d570 and ec36e3c. Its real roots (mpmath, 60 digits) are
# -2.5, -1.7e-316, 1.0000006985492323 and 1.0098700911692321, with two complex pairs at
# 1.011 +- 0.0016 i and 1.013 +- 0.0009 i. The slice u = t / 2^16 starts at t = 1, where p is
# 1.4e-15 against a fma noise of 5e-14: its noisy sign there (negative) hid the crossing at
# 1.0000007 and every runtime answered 1.009870091169232; the precise sign now decides.
SLICED_MISSED = [((1.27522373e-315, 7.375330973145643, -40.89367228170775, 91.07994702249495,
                   -100.11761183636594, 49.40799401036338, 0.20535343851918428, -9.829259794885488,
                   2.7719184684360205), 1.0116806122053246)]


# A crossing just before a slice's end, found by test_never_later_on_the_other_paths at
# WINDOW_FUZZ_COUNT=10000: real roots (mpmath) 0.99999999611408295 and 1.0000000039117157, a pair
# split by the boundary of the slices u = t / 2^-16 and u = t / 2^16 at t = 1, where p is 4.9e-19
# against a fma noise far above it. The first slice took the fma sign at its end (no crossing);
# the second started from the precise one; every runtime answered 1.0000000039117156, 7.8e-9
# late. A slice's end now takes the precise sign too.
SLICE_END_MISSED = [((-1.293069123e-314, -0.00017417165613203177, -0.00544679610068352,
                      -0.004458130127580139, 0.015700065640797217, 0.004632301783712171,
                      -0.010253269540113696), 2.0)]


@pytest.mark.parametrize("runtime", er.RUNTIMES)
def test_a_crossing_before_a_slices_end_is_not_missed(runtime: str, tmp_path: Path,
                                                      request: pytest.FixtureRequest) -> None:
    assert _wrong_or_late(SLICE_END_MISSED, _run(runtime, SLICE_END_MISSED, tmp_path, request)) == []


@pytest.mark.parametrize("runtime", er.RUNTIMES)
def test_a_crossing_on_the_sliced_path_is_not_missed(runtime: str, tmp_path: Path,
                                                     request: pytest.FixtureRequest) -> None:
    assert _wrong_or_late(SLICED_MISSED, _run(runtime, SLICED_MISSED, tmp_path, request)) == []


@pytest.mark.parametrize("runtime", er.RUNTIMES)
def test_a_touch_inside_the_band_is_not_late(runtime: str, tmp_path: Path,
                                             request: pytest.FixtureRequest) -> None:
    assert _wrong_or_late(IN_BAND_TOUCH, _run(runtime, IN_BAND_TOUCH, tmp_path, request)) == []
