"""Every variant proven: on parameters that satisfy its conditions, its polynomial is the
general equation's (Maxima's exact evaluation of the original program), the dispatcher picks
it, and `coefficients` reports its degree. Plus the strategy claims: far fewer operations, and
digits kept where the expanded form loses them all."""

from __future__ import annotations

import importlib.util
import subprocess
import zlib
from pathlib import Path

import pytest

from conftest import ROOT, require
from oracle import exact_coefficients, first_root_exact, random_samples

from max2code.codegen.emit import module_name
from max2code.codegen.generate import generate, load
from max2code.languages import LANGUAGES
from max2code.codegen.variants import family

EQUATIONS = sorted((ROOT / "equations").glob("*.mxm"))
PER_VARIANT = 12
COEF_TOL = 1e-13


@pytest.fixture(scope="module", params=EQUATIONS, ids=lambda p: p.stem)
def cases(request: pytest.FixtureRequest, maxima_exe: str):
    """(spec, poly, variants, samples as [(variant index, params)], exact per sample)."""
    path = request.param
    spec, poly = load(str(path.relative_to(ROOT)))
    variants = family(poly)
    assert len(variants) >= 2, "every shipped equation declares roles"
    samples = []
    for v in variants:
        for params in random_samples(poly.parameters, PER_VARIANT, seed=zlib.crc32(path.name.encode()) + v.index):
            samples.append((v.index, tuple(0.0 if n in v.zeros else x for n, x in zip(poly.parameters, params))))
    exact = exact_coefficients(path, poly.parameters, [p for _, p in samples])
    return spec, poly, variants, samples, exact


def _check(label: str, degree: int | None, coefs: list[float], exact) -> None:
    """`coefs` equal the exact polynomial; trailing entries beyond its degree must be ~0.
    With `degree` given, the code must also report exactly the exact degree."""
    want = list(exact.coefficients) + [0] * (len(coefs) - len(exact.coefficients))
    if degree is not None:
        assert degree == len(exact.coefficients) - 1, (
            f"{label}: degree {degree}, exact {len(exact.coefficients) - 1}")
    scale = max(abs(float(c)) for c in exact.coefficients)
    for k, (got, w) in enumerate(zip(coefs, want)):
        assert abs(got - float(w)) <= COEF_TOL * scale, f"{label}: c[{k}] = {got!r}, exact {float(w)!r}"


def test_shipped_orbiting_circles_has_the_promised_variants(maxima_exe: str) -> None:
    _, poly = load("equations/circles-orbit.mxm")
    variants = family(poly)
    by_label = {v.label: v.degree for v in variants}
    assert by_label["general"] == 8
    assert by_label["no orbit1, no orbit2"] == 4
    assert by_label["no orbit1, no orbit2, no accel1, no accel2"] == 2
    assert any("radius" in label for label in by_label)


def test_python_variants(cases, tmp_path: Path) -> None:
    spec, poly, variants, samples, exact = cases
    out = tmp_path / "mod.py"
    out.write_text(generate(spec, poly, LANGUAGES["python"], "module", str(out)).text)
    mspec = importlib.util.spec_from_file_location("mod", out)
    module = importlib.util.module_from_spec(mspec)
    mspec.loader.exec_module(module)
    assert len(module.VARIANTS) == len(variants)
    for (k, params), e in zip(samples, exact):
        assert module.variant(params) == k, f"dispatcher chose {module.variant(params)} for variant {k}"
        own = getattr(module, f"coefficients_v{k}")(params)
        _check(f"python v{k}", len(own) - 1, own, e)
        general = getattr(module, f"coefficients_v{len(variants) - 1}")(params)
        _check(f"python general at v{k}", None, general, e)


DRIVER = r"""
#include <stdio.h>
#include "mod.h"
int main(void) {{
    int k; double p[{name}_NPARAMS], c[{name}_DEGREE + 1];
    while (scanf("%d", &k) == 1) {{
        for (int i = 0; i < {name}_NPARAMS; i++) if (scanf("%la", &p[i]) != 1) return 1;
        int d;
        switch (k) {{ {cases} default: return 2; }}
        int chosen = {name}_variant(p);
        int d2 = {name}_coefficients(p, c);
        printf("%d %d %d", chosen, d, d2);
        for (int i = 0; i <= {name}_DEGREE; i++) printf(" %a", c[i]);
        printf("\n");
    }}
    return 0;
}}
"""


def test_c_variants(cases, tmp_path: Path) -> None:
    gcc = require("gcc")
    spec, poly, variants, samples, exact = cases
    result = generate(spec, poly, LANGUAGES["c"], "module", "mod.h")
    (tmp_path / "mod.h").write_text(result.text)
    name = module_name(spec)
    calls = " ".join(f"case {v.index}: d = {name}_coefficients_v{v.index}(p, c); break;" for v in variants)
    (tmp_path / "main.c").write_text(DRIVER.format(name=name, cases=calls))
    runtime = ROOT / "runtime" / "c"
    subprocess.run([gcc, "-std=c11", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O2", f"-I{runtime}",
                    "main.c", str(runtime / "max2code_roots.c"), "-o", "drv", "-lgsl", "-lgslcblas", "-lm"],
                   check=True, cwd=tmp_path)
    stdin = "".join(f"{k} " + " ".join(float.hex(x) for x in p) + "\n" for k, p in samples)
    lines = subprocess.run(["./drv"], input=stdin, capture_output=True, text=True, check=True,
                           cwd=tmp_path).stdout.splitlines()
    assert len(lines) == len(samples)
    for (k, _), line, e in zip(samples, lines, exact):
        chosen, d, d2, *cs = line.split()
        assert int(chosen) == k, f"C dispatcher chose {chosen} for variant {k}"
        assert int(d) == int(d2)
        _check(f"C v{k}", int(d2), [float.fromhex(x) for x in cs], e)


def test_optimised_strategy_is_cheaper_and_keeps_digits(maxima_exe: str, tmp_path: Path) -> None:
    """Orbiting circles at x = 1e8 and 1e8 + 0.5 (and y likewise): the optimised code's first
    root is within 1e-9 of the exact one; the expanded (paper's) code is shown failing."""
    path = ROOT / "equations" / "circles-orbit.mxm"
    spec, poly = load(str(path.relative_to(ROOT)))
    opt, exp = family(poly, "optimised")[-1], family(poly, "expanded")[-1]
    assert opt.label == exp.label == "general"
    assert exp.ops.total >= 5 * opt.ops.total, (exp.ops, opt.ops)
    values = dict(cx1=1e8, cy1=1e8, vx1=1.0, vy1=0.5, ax1=0.25, ay1=-0.125, ox1=0.5, oy1=0.25,
                  w1=0.125, r1=0.5, cx2=1e8 + 5.5, cy2=1e8 + 3.0, vx2=-0.75, vy2=-0.5, ax2=0.0625,
                  ay2=0.03125, ox2=-0.25, oy2=0.5, w2=-0.25, r2=0.75)
    params = tuple(values[n] for n in poly.parameters)
    (exact,) = exact_coefficients(path, poly.parameters, [params])
    want, _ = first_root_exact(exact.coefficients, 10.0)
    assert want is not None
    roots = {}
    for strategy in ("optimised", "expanded"):
        out = tmp_path / f"{strategy}.py"
        out.write_text(generate(spec, poly, LANGUAGES["python"], "module", str(out), strategy).text)
        mspec = importlib.util.spec_from_file_location(strategy, out)
        module = importlib.util.module_from_spec(mspec)
        mspec.loader.exec_module(module)
        roots[strategy] = module.first_root(params, 10.0)
    assert roots["optimised"] is not None and abs(roots["optimised"] - want) <= 1e-9 * want
    assert roots["expanded"] is None or abs(roots["expanded"] - want) > 1e-3 * want, roots
