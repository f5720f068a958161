"""Generated C and Python, compiled and run, against Maxima evaluating the original equation.

For every shipped equation: 120 random parameter sets; each language's coefficients and first
root are compared with exact coefficients (Maxima, rational arithmetic, the user's program as
written) and the exact first root (mpmath, 60 digits).
"""

from __future__ import annotations

import importlib.util
import subprocess
from pathlib import Path

import pytest

from conftest import ROOT, require
from oracle import TMAX, Exact, check_sample, sampled_equation

from max2code.codegen.generate import generate, load
from max2code.languages import LANGUAGES

EQUATIONS = sorted((ROOT / "equations").glob("*.mxm"))
SAMPLES = 120

DRIVER = r"""
#include <stdio.h>
#include <stdlib.h>
#include "{header}"
int main(void) {{
    double p[{name}_NPARAMS];
    for (;;) {{
        for (int i = 0; i < {name}_NPARAMS; i++)
            if (scanf("%la", &p[i]) != 1) return 0;
        double c[{name}_DEGREE + 1], t = -1.0;
        int degree = {name}_coefficients(p, c);
        int status = {name}_first_root(p, {tmax}, &t);
        printf("%d", degree);
        for (int i = 0; i <= degree; i++) printf(" %a", c[i]);
        printf(" | %d %a\n", status, status == 1 ? t : 0.0);
    }}
}}
"""


@pytest.fixture(scope="module", params=EQUATIONS, ids=lambda p: p.stem)
def equation(request: pytest.FixtureRequest, maxima_exe: str) -> tuple[Path, object, list[Exact]]:
    spec, poly, exact = sampled_equation(request.param, SAMPLES)
    return request.param, (spec, poly), exact


def test_c_module_matches_oracle(equation, tmp_path: Path) -> None:
    gcc = require("gcc")
    path, (spec, poly), exact = equation
    name = "eq"
    header = tmp_path / f"{path.stem}.h"
    result = generate(spec, poly, LANGUAGES["c"], "module", str(header))
    header.write_text(result.text)
    cname = result.text.split("#define ")[2].split("_NPARAMS")[0]
    (tmp_path / "main.c").write_text(DRIVER.format(header=header.name, name=cname, tmax=TMAX))
    exe = tmp_path / name
    runtime = ROOT / "runtime" / "c"
    subprocess.run([gcc, "-std=c11", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O2",
                    f"-I{runtime}", f"-I{tmp_path}", str(tmp_path / "main.c"),
                    str(runtime / "max2code_roots.c"), "-o", str(exe),
                    "-lgsl", "-lgslcblas", "-lm"], check=True)
    stdin = "\n".join(" ".join(float.hex(v) for v in e.params) for e in exact) + "\n"
    out = subprocess.run([str(exe)], input=stdin, capture_output=True, text=True, check=True)
    lines = out.stdout.splitlines()
    assert len(lines) == len(exact)
    for i, (line, e) in enumerate(zip(lines, exact)):
        left, right = line.split(" | ")
        fields = left.split()
        coefs = [float.fromhex(x) for x in fields[1:]]
        assert int(fields[0]) == len(coefs) - 1
        status, t = right.split()
        check_sample(e, coefs, float.fromhex(t) if status == "1" else None, f"C sample {i}")


def test_python_module_matches_oracle(equation, tmp_path: Path) -> None:
    path, (spec, poly), exact = equation
    out = tmp_path / f"{path.stem.replace('-', '_')}.py"
    out.write_text(generate(spec, poly, LANGUAGES["python"], "module", str(out)).text)
    module_spec = importlib.util.spec_from_file_location(out.stem, out)
    assert module_spec and module_spec.loader
    module = importlib.util.module_from_spec(module_spec)
    module_spec.loader.exec_module(module)
    assert module.DEGREE == poly.degree
    assert list(module.PARAMS) == list(poly.parameters)
    for i, e in enumerate(exact):
        coefs = module.coefficients(e.params)
        check_sample(e, coefs, module.first_root(e.params, TMAX), f"Python sample {i}")


def test_python_module_is_deterministic(equation, tmp_path: Path) -> None:
    path, (spec, poly), _ = equation
    first = generate(spec, poly, LANGUAGES["python"], "module", "x.py").text
    spec2, poly2 = load(str(path))
    assert generate(spec2, poly2, LANGUAGES["python"], "module", "x.py").text == first
