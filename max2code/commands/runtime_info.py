"""`max2code runtime`: where each language's runtime lives and how to use it, like pkg-config.

    max2code runtime                       everything, one language per paragraph
    max2code runtime --lang c --cflags     -I/path/to/runtime/c
    max2code runtime --lang c --sources    /path/to/runtime/c/max2code_roots.c
    max2code runtime --lang c --libs       -lgsl -lgslcblas -lm
    max2code runtime --lang rust --dir     /path/to/runtime/rust   (a Cargo path dependency)
    max2code runtime --lang python --dir   the folder to put on PYTHONPATH for max2code_runtime
    max2code runtime --lang m2 --cflags    -fiso -I/path/to/runtime/m2   (Max2codeRoots.def)
    max2code runtime --cmake-dir           a folder with max2codeConfig.cmake, for
                                           cmake -Dmax2code_DIR=... and find_package(max2code)

Build systems call it once at configure time (Make: `$(shell ...)`, CMake: `execute_process`,
Cargo: a build script) instead of hard-coding the checkout's layout. Each query prints one line.
"""

from __future__ import annotations

import argparse
import hashlib
import site
import sys
from pathlib import Path

from .. import __version__, cache
from ..output import write_if_changed
from ..paths import PACKAGE, runtime_dir

def info(lang: str) -> dict[str, str]:
    """The answers for one language, from its registry entry; every value is one line of text
    ('' when not relevant). A language without build flags gets its runtime folder."""
    from ..languages import REGISTRY

    entry = REGISTRY.get(lang)
    if entry is not None and entry.runtime is not None:
        return entry.runtime()
    return {"dir": str(runtime_dir(lang)), "cflags": "", "sources": "", "libs": "",
            "note": "no build flags known for this language: its runtime is in 'dir'"}


CONFIG = """\
# max2code's CMake package, written by `max2code runtime --cmake-dir` for the max2code that
# MAX2CODE_COMMAND below runs: find_package(max2code) with max2code_DIR set to this folder gives
# max2code_generate() and the max2code::runtime target (max2code-functions.cmake, included).
set(max2code_VERSION {version})
# the languages of this max2code's registry, each with its module's extension
set(MAX2CODE_LANGUAGE_EXTENSIONS {extensions})
if(NOT MAX2CODE_COMMAND)
  set(MAX2CODE_COMMAND {command} CACHE STRING "the command that runs max2code")
endif()
include({functions})
"""

CONFIG_VERSION = """\
# Written by `max2code runtime --cmake-dir`: this max2code is {version}; any version of the
# same major number is compatible.
set(PACKAGE_VERSION {version})
if(PACKAGE_FIND_VERSION VERSION_GREATER PACKAGE_VERSION
   OR NOT PACKAGE_FIND_VERSION_MAJOR STREQUAL "{major}")
  set(PACKAGE_VERSION_COMPATIBLE FALSE)
else()
  set(PACKAGE_VERSION_COMPATIBLE TRUE)
  if(PACKAGE_FIND_VERSION STREQUAL PACKAGE_VERSION)
    set(PACKAGE_VERSION_EXACT TRUE)
  endif()
endif()
"""


def _bracket(text: str) -> str:
    """A CMake bracket argument: literal, whatever the text holds."""
    level = 1
    while f"]{'=' * level}]" in text:
        level += 1
    return f"[{'=' * level}[{text}]{'=' * level}]"


def cmake_dir() -> Path:
    """Write max2codeConfig.cmake (and its version file) for this max2code, run by this Python,
    into the cache folder (`cmake/<digest>/`, rewritten only when it changes) and return the
    folder. The functions themselves are the package's cmake/max2code-functions.cmake; the
    config only names the command that runs this max2code (with PYTHONPATH when the package
    is not where the interpreter looks by itself, as in a checkout)."""
    root = PACKAGE.parent
    command = [sys.executable, "-m", "max2code"]
    if str(root) not in site.getsitepackages() + [site.getusersitepackages()]:
        command = ["${CMAKE_COMMAND}", "-E", "env", f"PYTHONPATH={root}", *command]
    words = " ".join(w if w.startswith("${") else _bracket(w) for w in command)
    functions = _bracket((PACKAGE / "cmake" / "max2code-functions.cmake").as_posix())
    from ..languages import LANGUAGES
    extensions = " ".join(f"{name} {lang.extension}" for name, lang in LANGUAGES.items())
    config = CONFIG.format(functions=functions, version=__version__, command=words,
                           extensions=extensions)
    version = CONFIG_VERSION.format(version=__version__, major=__version__.split(".")[0])
    folder = cache.directory() / "cmake" / hashlib.sha256(config.encode()).hexdigest()[:16]
    folder.mkdir(parents=True, exist_ok=True)
    write_if_changed(str(folder / "max2codeConfig.cmake"), config)
    write_if_changed(str(folder / "max2codeConfigVersion.cmake"), version)
    return folder


def _languages() -> list[str]:
    from ..languages import LANGUAGES
    return sorted(LANGUAGES)


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(prog="max2code runtime",
                                 description="Where each language's runtime lives and the flags "
                                             "to use it (like pkg-config).")
    ap.add_argument("--lang", metavar="LANG", help="one language (default: all, described)")
    group = ap.add_mutually_exclusive_group()
    for flag, what in (("dir", "the runtime's folder (Rust: the crate; Python: for PYTHONPATH)"),
                       ("cflags", "compiler flags (C: -I; Modula-2: gm2 flags)"),
                       ("sources", "source file(s) to compile into the program"),
                       ("libs", "linker flags"),
                       ("cargo", "the Cargo.toml dependency line (Rust)"),
                       ("importable", "'yes' if max2code_runtime imports here (Python)")):
        group.add_argument(f"--{flag}", dest="query", action="store_const", const=flag, help=what)
    ap.add_argument("--cmake-dir", action="store_true",
                    help="write the CMake package config for this max2code and print its folder "
                         "(cmake -Dmax2code_DIR=...; find_package(max2code))")
    opts = ap.parse_args(argv)
    if opts.cmake_dir:
        if opts.lang or opts.query:
            ap.error("--cmake-dir takes no --lang and no other query")
        print(cmake_dir())
        return 0
    langs = _languages()
    if opts.lang is not None and opts.lang not in langs:
        ap.error(f"unknown language {opts.lang!r} (choose from {', '.join(langs)})")
    if opts.query:
        if opts.lang is None:
            ap.error(f"--{opts.query} needs --lang")
        values = info(opts.lang)
        if opts.query not in values:
            ap.error(f"--{opts.query} does not apply to {opts.lang}")
        print(values[opts.query])
        return 0
    for lang in [opts.lang] if opts.lang else langs:
        print(f"[{lang}]")
        for k, v in info(lang).items():
            if v:
                print(f"{k}: {v}")
        print()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
