"""The options several commands share: those of every command that runs Maxima on a .mxm
(one definition, so that an error's advice such as --allow-unsafe-maxima holds in each), and
-q. Kept out of cli.py so that the subcommands never import back from the entry point."""

from __future__ import annotations

import argparse
import math
from collections.abc import Iterable

from .. import cache
from ..maxima import session as maxima
from ..diagnostics import Diagnostic


def seconds(text: str) -> float:
    """--timeout's type: a finite number of seconds above 0 (a usage error otherwise)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected seconds, not {text!r}") from None
    if not (0 < value < math.inf):
        raise argparse.ArgumentTypeError(f"must be a finite number of seconds above 0, not {text}")
    return value


def mebibytes(text: str) -> int:
    """--maxima-memory's type: 0 (no limit), or at least what GCL needs to start."""
    from ..maxima.confine import MIN_MEMORY_MIB

    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a whole number of MiB, not {text!r}") from None
    if value < 0 or 0 < value < MIN_MEMORY_MIB:
        raise argparse.ArgumentTypeError(f"must be 0 (no limit) or at least {MIN_MEMORY_MIB} "
                                         f"MiB (what GCL needs to start), not {value}")
    return value


def add_maxima_options(ap: argparse.ArgumentParser) -> None:
    """The options of every command that runs Maxima on a .mxm (README: Security), so that an
    error's advice (--allow-unsafe-maxima, --maxima-memory) holds in each."""
    from ..maxima.confine import DEFAULT_MEMORY_MIB

    ap.add_argument("--timeout", type=seconds, default=maxima.DEFAULT_TIMEOUT, metavar="SECONDS",
                    help=f"limit on one Maxima run (default {maxima.DEFAULT_TIMEOUT:g})")
    ap.add_argument("--no-cache", action="store_true",
                    help="neither read nor write the cache (Maxima results; build's outputs)")
    ap.add_argument("--maxima-memory", type=mebibytes, default=None, metavar="MIB",
                    help=f"memory (address space) one Maxima run may use (default "
                         f"{DEFAULT_MEMORY_MIB}; 0: no limit)")
    ap.add_argument("--allow-unsafe-maxima", action="store_true",
                    help="let the .mxm program run shell commands, Lisp, file input/output and "
                         "plotting (refused by default: see README, Security)")


def apply_maxima_options(opts: argparse.Namespace) -> None:
    if opts.no_cache:
        cache.disable()
    maxima.configure(opts.maxima_memory, opts.allow_unsafe_maxima)


def add_quiet_option(ap: argparse.ArgumentParser) -> None:
    """-q: notes are advice (a role that gives no variant); a build log may not want them.
    Warnings and errors still print."""
    ap.add_argument("-q", "--quiet", action="store_true",
                    help="do not print notes (warnings and errors still print)")


def shown(diagnostics: Iterable[Diagnostic], quiet: bool) -> list[str]:
    """The diagnostics to print: all of them, or with -q all but the notes."""
    return [str(d) for d in diagnostics if not (quiet and d.severity == "note")]
