"""Which C sources the cffi backend was built from (build.py writes the digest, _cbackend
checks it), and the binding's own C: shared by both so that neither imports the other."""
from __future__ import annotations

import hashlib
from pathlib import Path

STAMP = Path(__file__).resolve().parent / "_roots_c.stamp"

# The declarations cffi binds.  m2c_first_root_packed is the binding's own (BINDING_C): one
# call, no out-parameters, so that a Python call needs no buffers and cffi converts the
# coefficient list straight into a temporary array (measured with python -m timeit on
# c = [1.0] * 9, a solve that ends at once: 0.36 us a call, against 0.54 us for copying into a
# kept buffer and calling m2c_first_root_ex with two out-pointers; bench/roots.py's Python
# (C backend) column went from 2.9-19.6x C to 2.4-14.7x); the other methods and the skin take
# it.  The common call (the default method, no skin) takes m2c_packed_1 .. m2c_packed_17: the
# same for that many coefficients, passed as double arguments, which cffi converts at 0.5-0.7
# of the cost of the same numbers as a list (_cbackend.BY_LEN).
MAX_COEFFS = 17
CDEF = """
int m2c_first_root_ex(const double c[], int degree, double tmax, double *t, int method, int *graze);
int m2c_first_root_skin(const double c[], int degree, double tmax, double eps, double *t, int *graze);
int m2c_first_roots(const double c[], int m, int degree, double tmax, double eps, double t[], int status[]);
double m2c_first_root_packed(const double c[], int degree, double tmax, int method, double eps);
""" + "".join(f"double m2c_packed_{k}({', '.join(['double'] * (k + 1))});\n"
              for k in range(1, MAX_COEFFS + 1))

# m2c_first_root_ex (eps = 0) or m2c_first_root_skin (eps != 0, the default method only), its
# three results in one double: the root t (> 0) for a crossing, -t for a touch, +0.0 for no
# root, NaN for invalid input (_cbackend.unpack reads it back).
BINDING_C = """
#include <math.h>
#include "max2code_roots.h"
double m2c_first_root_packed(const double c[], int degree, double tmax, int method, double eps)
{
    double t = 0;
    int g = 0;
    int st = eps == 0 ? m2c_first_root_ex(c, degree, tmax, &t, method, &g)
                      : method == M2C_METHOD_INTERVAL ? m2c_first_root_skin(c, degree, tmax, eps, &t, &g)
                                                      : -1;
    return st == 1 ? (g ? -t : t) : st == 0 ? 0.0 : NAN;
}
""" + "".join(
    f"static double m2c_packed_{k}({', '.join(f'double c{i}' for i in range(k))}, double tmax)\n"
    f"{{\n    const double c[{k}] = {{{', '.join(f'c{i}' for i in range(k))}}};\n"
    f"    return m2c_first_root_packed(c, {k - 1}, tmax, M2C_METHOD_INTERVAL, 0.0);\n}}\n"
    for k in range(1, MAX_COEFFS + 1))


def source_files(src: Path) -> list[Path]:
    """The C runtime's sources in the folder src: the file compiled, its header and the parts
    it includes (roots/*.inc, one translation unit)."""
    return [src / "max2code_roots.c", src / "max2code_roots.h", *sorted(src.glob("roots/*.inc"))]


def source_digest(src: Path) -> str:
    h = hashlib.sha256()
    for path in source_files(src):
        h.update(path.relative_to(src).as_posix().encode() + b"\0")
        h.update(path.read_bytes())
    h.update((CDEF + BINDING_C).encode())
    return h.hexdigest()
