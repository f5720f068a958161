"""The C runtime's build variants answer alike, bit for bit.

Two of the runtime's speed-ups are copies of code that the compiler chooses between, each
promised to compute the same operations in the same order, and the runtime promises the same
bits from GCC and Clang in any mode, with no flag of the user's: it keeps a * x + b unfused
itself (#pragma STDC FP_CONTRACT OFF for Clang, whose default fuses within an expression;
#pragma GCC optimize("fp-contract=off") for GCC, whose GNU modes fuse everywhere the target
has the instruction -- in the fma copies below even without -mfma):

- the precise kernels compiled for the fma instruction beside their plain builds, picked per call
  by the CPU (FMA_DISPATCH; off with -DM2C_NO_FMA_DISPATCH, as on a CPU without it);
- the solve copied for degrees 2, 4 and 8 with the degree a constant and every hot call inlined
  (DEGREE_CLONES; off with -DM2C_NO_DEGREE_CLONES);
- GCC's GNU mode (its default), also at -O3 with -march=native (fused everywhere where
  allowed; the CPU's own instructions);
- Clang (installed by scripts/setup), whose `flatten` makes the degree copies too, and whose
  <complex.h> on glibc has no CMPLX (the closed quartic's complex factors are built without it).

Each variant is built as the tests' line driver and run on the benchmark's families (touches,
clusters, complex pairs near the window: where the precise kernels and the certified tests
decide) and on adversarial vectors, by the default method with and without the contact skin,
the no-graze one and the closed form (degrees 3 and 4; the others: the default); every answer (status,
root, graze flag) must match the default build's (gcc's, C11); the input has hundreds of
degree-2, 4 and 8 lines.  And the default builds of both compilers hold the copies (their
symbols): were they silently off, the comparison with -DM2C_NO_DEGREE_CLONES would compare the
generic code with itself.
"""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from conftest import require

from . import fuzz
from . import test_fuzz_runtimes as tf

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def lines() -> list[str]:
    sys.path.insert(0, str(ROOT / "bench"))
    import roots  # noqa: E402  (bench/roots.py's families)

    vecs = [(c, t) for _, c, t in roots.polynomials(60)] + fuzz.vectors(2000, seed=29)
    return [tf.c_line(m, c, t) for c, t in vecs for m in ("0", "1", "0:1e-9", "3")]


def _answers(exe: Path, lines: list[str]) -> list[str]:
    r = subprocess.run([str(exe)], input="\n".join(lines) + "\n", capture_output=True,
                       text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    out = r.stdout.splitlines()
    assert len(out) == len(lines)
    return out


def _assert_same(lines: list[str], default_answers: list[str], out: list[str],
                 what: str) -> None:
    """Every answer as the default build's, else the first 20 that differ."""
    differ = [f"{ln}: {a} / {b}" for ln, a, b in zip(lines, default_answers, out) if a != b]
    assert not differ, f"{len(differ)} answers differ {what}:\n" + "\n".join(differ[:20])


@pytest.fixture(scope="module")
def default_answers(lines: list[str], tmp_path_factory: pytest.TempPathFactory) -> list[str]:
    exe = tf.build_driver(tmp_path_factory.mktemp("default") / "roots_driver")
    return _answers(exe, lines)


@pytest.mark.parametrize("cc, extra", [
    ("gcc", ["-DM2C_NO_FMA_DISPATCH"]),
    ("gcc", ["-DM2C_NO_DEGREE_CLONES"]),
    ("gcc", ["-std=gnu11"]),
    ("gcc", ["-std=gnu11", "-O3", "-march=native"]),
    ("clang", []),
    ("clang", ["-DM2C_NO_DEGREE_CLONES"]),
    ("clang", ["-march=native"]),
])
def test_variant_answers_as_the_default_build(cc: str, extra: list[str], lines: list[str],
                                              default_answers: list[str],
                                              tmp_path: Path) -> None:
    exe = tf.build_driver(tmp_path / "roots_driver", extra=extra, cc=cc)
    out = _answers(exe, lines)
    degrees = [ln.split()[2] for ln in lines]
    found = [ln for ln in default_answers if ln.startswith("1 ")]
    assert len(found) > 500 and min(degrees.count("2"), degrees.count("4")) > 300
    assert degrees.count("8") > 2000
    _assert_same(lines, default_answers, out, "with " + " ".join([cc, *extra]))


@pytest.mark.parametrize("cc, extra", [
    ("gcc", []), ("clang", []), ("gcc", ["-march=native"]), ("gcc", ["-DM2C_NO_FMA_DISPATCH"]),
])
def test_default_build_has_the_degree_copies(cc: str, extra: list[str], tmp_path: Path) -> None:
    """The copies exist as code of their own: bernstein_clear_8 was once, in builds where the
    inlining its body asked for was only a hint (-march=native, no fma dispatch), a jump of a
    few bytes into the general body."""
    nm = require("nm")
    obj = tmp_path / "roots.o"
    r = subprocess.run([require(cc), "-O2", "-std=c11", *extra, "-c",
                        str(tf.C_DIR / "max2code_roots.c"), "-o", str(obj)],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    sizes = {}
    for row in subprocess.run([nm, "-S", str(obj)], capture_output=True, text=True,
                              check=True).stdout.splitlines():
        parts = row.split()
        if len(parts) == 4:
            sizes[parts[3]] = int(parts[1], 16)
    copies = {"solve_2", "solve_4", "solve_8", "first_root_interval_4", "first_root_interval_8",
              "bernstein_clear_8"}
    assert copies <= set(sizes), sorted(copies - set(sizes))
    small = {name: sizes[name] for name in copies if sizes[name] < 256}
    assert not small, f"copies of a few bytes (a jump, not a copy): {small}"


def test_no_uninitialised_reads(lines: list[str], default_answers: list[str],
                                tmp_path: Path) -> None:
    """Clang's MemorySanitizer on the whole input: the written-out forms read tables filled
    only as far as they need (point_at's degree-4 form, taylor_table's zeros up to `top`), and
    a form reading zeros never written once gave four wrong answers under Clang alone.  GSL
    (not instrumented) is left out: the lines do not use it."""
    exe = tf.build_driver(tmp_path / "roots_driver_msan", cc="clang",
                          extra=["-O1", "-g", "-fsanitize=memory",
                                 "-fsanitize-memory-track-origins", "-DM2C_NO_GSL"])
    out = _answers(exe, lines)
    _assert_same(lines, default_answers, out, "under MemorySanitizer")
