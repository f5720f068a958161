"""Build the C backend of max2code_runtime (``_roots_c``, cffi API mode) in place.

    python -m max2code_runtime.build          # scripts/setup runs this

Compiles runtime/c/max2code_roots.c (found beside this package in a checkout, or in the
installed max2code package's data) into an extension module next to this file, with
-O2 and -ffp-contract=off (no fused multiply-adds beyond the explicit fma calls: the answers
stay bit-identical to the pure-Python and Rust ports).  Links GSL when its header is there
(M2C_METHOD_GSL), else builds without it.  Needs cffi and a C compiler; exits non-zero
with the reason otherwise.
"""
from __future__ import annotations

import shutil
import sys
import tempfile
from pathlib import Path

from ._source import BINDING_C, CDEF, STAMP, source_digest

HERE = Path(__file__).resolve().parent


def c_dir() -> Path:
    for cand in (HERE.parent.parent / "c", HERE.parent / "max2code" / "_data" / "runtime" / "c"):
        if (cand / "max2code_roots.c").exists():
            return cand
    try:
        from max2code.paths import runtime_dir  # type: ignore[import-not-found]
        return Path(runtime_dir()) / "c"
    except Exception as exc:  # noqa: BLE001 - any failure means "not found"
        raise SystemExit(f"max2code_runtime.build: runtime/c/max2code_roots.c not found ({exc})")


def main() -> int:
    try:
        import cffi
    except ImportError:
        print("max2code_runtime.build: cffi is not installed (pip install cffi)", file=sys.stderr)
        return 1
    src = c_dir()
    gsl = Path("/usr/include/gsl/gsl_poly.h").exists()
    ffi = cffi.FFI()
    ffi.cdef(CDEF)
    ffi.set_source("max2code_runtime._roots_c", BINDING_C,
                   sources=[str(src / "max2code_roots.c")], include_dirs=[str(src)],
                   libraries=(["gsl", "gslcblas"] if gsl else []) + ["m"],
                   define_macros=[] if gsl else [("M2C_NO_GSL", "1")],
                   extra_compile_args=["-O2", "-ffp-contract=off"])
    with tempfile.TemporaryDirectory() as tmp:
        lib = Path(ffi.compile(tmpdir=tmp, verbose=False))
        dest = HERE / lib.name
        tmp_dest = dest.with_suffix(".tmp")
        shutil.copyfile(lib, tmp_dest)
        tmp_dest.replace(dest)
    STAMP.write_text(source_digest(src) + "\n")
    print(f"max2code_runtime.build: wrote {dest}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
