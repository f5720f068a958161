"""Command line: `max2code --lang=X FILE.mxm -o OUT`, and `max2code build` for the main job."""

from __future__ import annotations

import argparse
import importlib
import os
import sys

from . import __version__, cache, depfile, maxima
from .diagnostics import Max2CodeError
from .output import write_if_changed


# `max2code NAME ...` runs the module's main(argv); one line per subcommand.
SUBCOMMANDS = {
    "build": "build",
    "check": "check",
    "report": "report",
    "roles": "roles",
    "runtime": "runtime_info",
    "scene": "scene",
    "sim": "sim",
}


def _parser() -> argparse.ArgumentParser:
    from .languages import LANGUAGES
    from .variants import DEFAULT_STRATEGY, STRATEGIES

    ap = argparse.ArgumentParser(
        prog="max2code",
        description="Turn a Maxima collision equation (.mxm) into C, Python, ... code. "
                    "Subcommands: 'max2code build --help', 'max2code runtime --help'.")
    ap.add_argument("--version", action="version", version=f"max2code {__version__}")
    ap.add_argument("--lang", choices=sorted(LANGUAGES), required=True,
                    help="target language")
    ap.add_argument("-o", "--output", default="-", metavar="FILE",
                    help="output file ('-' for standard output, the default)")
    ap.add_argument("--emit", choices=["auto", "fragment", "module"], default="auto",
                    help="fragment: the paper's initialise/terms/finalise text; module: the "
                         "functions of the generated-code contract; auto (default): fragment if "
                         "the .mxm has term blocks, else module")
    ap.add_argument("--timeout", type=float, default=maxima.DEFAULT_TIMEOUT, metavar="SECONDS",
                    help=f"limit on one Maxima run (default {maxima.DEFAULT_TIMEOUT:g})")
    ap.add_argument("-MD", dest="md", action="store_true",
                    help="also write a Make/Ninja dependency file OUTPUT.d (the .mxm and the "
                         "files its program loads)")
    ap.add_argument("-MF", "--depfile", metavar="FILE.d",
                    help="write the dependency file to FILE.d (implies -MD)")
    ap.add_argument("-MP", dest="mp", action="store_true",
                    help="add an empty rule for each dependency, as gcc -MP does")
    ap.add_argument("--no-cache", action="store_true",
                    help="neither read nor write the cache of Maxima results")
    ap.add_argument("--strategy", choices=STRATEGIES, default=DEFAULT_STRATEGY,
                    help="optimised (default): relative quantities first, expansion in t only, "
                         "shared subexpressions; expanded: the paper's fully expanded coefficients")
    ap.add_argument("--no-variants", action="store_true",
                    help="emit only the general polynomial, without the role variants")
    ap.add_argument("input", metavar="FILE.mxm")
    return ap


def report(exc: Max2CodeError) -> int:
    for diag in exc.diagnostics:
        print(diag, file=sys.stderr)
    return 1


def main(argv: list[str] | None = None) -> int:
    """Entry point; an unexpected failure is reported in one line, not as a traceback."""
    try:
        return _main(argv)
    except Max2CodeError as exc:
        return report(exc)
    except KeyboardInterrupt:
        return 130
    except Exception as exc:  # noqa: BLE001 - the last line of defence for build logs
        if os.environ.get("MAX2CODE_DEBUG"):
            raise
        print(f"max2code: internal error: {type(exc).__name__}: {exc} "
              f"(set MAX2CODE_DEBUG=1 for a traceback, and please report it)", file=sys.stderr)
        return 2


def _main(argv: list[str] | None) -> int:
    args = list(sys.argv[1:] if argv is None else argv)
    if args and args[0] in SUBCOMMANDS:
        module = importlib.import_module(f".{SUBCOMMANDS[args[0]]}", __package__)
        return int(module.main(args[1:]))
    ap = _parser()
    opts = ap.parse_args(args)
    dep_path = opts.depfile or (depfile.default_name(opts.output) if opts.md else None)
    if dep_path and opts.output == "-":
        ap.error("a dependency file (-MD, -MF) needs an output file (-o FILE)")
    if opts.no_cache:
        cache.disable()
    from .generate import generate, load
    from .languages import LANGUAGES

    try:
        spec, poly = load(opts.input, opts.timeout)
        out_name = "<stdout>" if opts.output == "-" else opts.output
        result = generate(spec, poly, LANGUAGES[opts.lang], opts.emit, out_name,
                          opts.strategy, not opts.no_variants)
        for warning in result.warnings:
            print(warning, file=sys.stderr)
        for path, text in result.companions:  # first: a definition precedes its implementation
            write_if_changed(path, text)
        write_if_changed(opts.output, result.text)
        if dep_path:
            targets = [opts.output, *(path for path, _ in result.companions)]
            deps = [opts.input, *depfile.loaded_files(spec.program.statements)]
            write_if_changed(dep_path, depfile.text(targets, deps, opts.mp))
    except Max2CodeError as exc:
        return report(exc)
    except KeyboardInterrupt:
        return 130
    return 0
