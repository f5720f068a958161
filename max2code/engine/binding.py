"""The cffi binding (ABI mode): the declarations are read from the C header itself (between
its `cdef-begin` and `cdef-end` markers), so the two cannot drift apart."""

from __future__ import annotations

import re
from functools import lru_cache
from typing import Any

from .build import header, library


def declarations() -> str:
    text = header().read_text()
    m = re.search(r"/\* cdef-begin \*/(.*)/\* cdef-end \*/", text, re.S)
    if not m:
        raise RuntimeError(f"{header()}: no cdef-begin/cdef-end section")
    return re.sub(r"\bM2C_API\s+", "", m.group(1))


@lru_cache(maxsize=1)
def load() -> tuple[Any, Any]:
    """(ffi, lib), building the library on first use."""
    import cffi

    ffi = cffi.FFI()
    ffi.cdef(declarations())
    lib = ffi.dlopen(str(library()))
    return ffi, lib
