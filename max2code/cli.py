"""Command line: `max2code --lang=X FILE.mxm -o OUT`, and `max2code build` for the main job."""

from __future__ import annotations

import argparse
import importlib
import math
import os
import signal
import sys

from . import __version__
from .maxima import children, depfile
from .diagnostics import Max2CodeError
from .commands.options import add_maxima_options, add_quiet_option, apply_maxima_options, shown
from .output import require_folder, write_if_changed


# `max2code NAME ...` runs the module's main(argv); one line per subcommand.
SUBCOMMANDS = {
    "build": "commands.build",
    "check": "commands.check",
    "pge": "pge.command",
    "report": "commands.report",
    "roles": "commands.roles",
    "runtime": "commands.runtime_info",
    "scene": "commands.scene",
    "serve": "commands.serve",
    "sim": "commands.sim",
    "vectors": "commands.vectors",
}
# What each subcommand does, for the top-level --help (tests/test_cli.py: one per subcommand).
SUMMARIES = {
    "build": "generate every language for each .mxm (default: the current folder's), with a "
             "summary",
    "check": "build each equation in every language and compare with the oracle's vectors",
    "pge": "run a PGE game unmodified on the predictive engine: window, or headless with pictures",
    "report": "the variant report: Markdown, JSON and HTML with a chart",
    "roles": "which parameters (alone, in pairs, as vectors) are worth a role",
    "runtime": "where the runtimes are, and the flags and CMake package to build with them",
    "scene": "every pair's first contact in a frozen scene, predicted by the engine",
    "serve": "serve a scene to browsers: an authoritative event server and its client page",
    "sim": "run a scene in the predictive engine: event log, pictures (GIF, MP4, PNG, SVG)",
    "vectors": "test vectors for any .mxm from the independent oracle (Maxima + mpmath)",
}


def _parser() -> argparse.ArgumentParser:
    from .languages import LANGUAGES
    from .codegen.variants import DEFAULT_STRATEGY, STRATEGIES

    ap = argparse.ArgumentParser(
        prog="max2code",
        description="Turn a Maxima collision equation (.mxm) into C, Python, Rust or Modula-2 "
                    "code: max2code --lang=L FILE.mxm [-o OUT]. Or run a subcommand "
                    "(max2code NAME --help for its options).",
        epilog="subcommands:\n" + "\n".join(f"  {name:<9} {SUMMARIES.get(name, '')}"
                                            for name in SUBCOMMANDS),
        formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--version", action="version", version=f"max2code {__version__}")
    ap.add_argument("--lang", choices=sorted(LANGUAGES), required=True,
                    help="target language")
    ap.add_argument("-o", "--output", default="-", metavar="FILE",
                    help="output file ('-' for standard output, the default)")
    ap.add_argument("--emit", choices=["auto", "fragment", "module"], default="auto",
                    help="fragment: the paper's initialise/terms/finalise text; module: the "
                         "functions of the generated-code contract; auto (default): fragment if "
                         "the .mxm has term blocks, else module")
    ap.add_argument("-MD", dest="md", action="store_true",
                    help="also write a Make/Ninja dependency file OUTPUT.d (the .mxm and the "
                         "files its program loads)")
    ap.add_argument("-MF", "--depfile", metavar="FILE.d",
                    help="write the dependency file to FILE.d (implies -MD)")
    ap.add_argument("-MP", dest="mp", action="store_true",
                    help="add an empty rule for each dependency, as gcc -MP does")
    add_maxima_options(ap)
    add_quiet_option(ap)
    ap.add_argument("--strategy", choices=STRATEGIES, default=DEFAULT_STRATEGY,
                    help="optimised (default): relative quantities first, expansion in t only, "
                         "shared subexpressions; expanded: the paper's fully expanded coefficients")
    ap.add_argument("--no-variants", action="store_true",
                    help="emit only the general polynomial, without the role variants")
    ap.add_argument("--print-name", action="store_true",
                    help="print the name the outputs are named after (the declared 'function', "
                         "else the file's stem) and exit; reads only the header, no Maxima")
    ap.add_argument("input", metavar="FILE.mxm")
    return ap


def report(exc: Max2CodeError) -> int:
    for diag in exc.diagnostics:
        print(diag, file=sys.stderr)
    return 1


def main(argv: list[str] | None = None) -> int:
    """Entry point; an unexpected failure is reported in one line, not as a traceback.
    SIGTERM, SIGINT and SIGHUP stop every Maxima this process started (maxima/children.py) and exit
    with 128 + the signal's number."""
    children.install_signal_handlers()
    try:
        try:
            return _main(argv)
        finally:  # also after --help's SystemExit: a closed pipe shows here at the latest
            sys.stdout.flush()
    except BrokenPipeError:
        return closed_pipe()
    except Max2CodeError as exc:
        return report(exc)
    except children.Interrupted as exc:
        return 128 + exc.signum
    except KeyboardInterrupt:
        return 130
    except Exception as exc:  # noqa: BLE001 - the last line of defence for build logs
        if os.environ.get("MAX2CODE_DEBUG"):
            raise
        print(f"max2code: internal error: {type(exc).__name__}: {exc} "
              f"(set MAX2CODE_DEBUG=1 for a traceback, and please report it)", file=sys.stderr)
        return 2


def closed_pipe() -> int:
    """The reader of our output went away (`max2code scene ... | head -3`): stop quietly, as
    Unix tools do, with the status of a process killed by SIGPIPE (128 + 13). Standard output
    is pointed at /dev/null first, so that the interpreter's last flush cannot fail again."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except OSError:
        pass
    return 128 + signal.SIGPIPE


def print_name(path: str, lang_name: str) -> int:
    """What `max2code build` and CMake's max2code_generate() name an equation's outputs after,
    so that a build system can know the file before generating it."""
    from .codegen.emit import check_module_name, module_name
    from .languages import LANGUAGES
    from .front.parse import parse_file

    spec = parse_file(path)
    check_module_name(spec, LANGUAGES[lang_name])
    print(module_name(spec))
    return 0


def _main(argv: list[str] | None) -> int:
    args = list(sys.argv[1:] if argv is None else argv)
    if args and args[0] in SUBCOMMANDS:
        module = importlib.import_module(f".{SUBCOMMANDS[args[0]]}", __package__)
        return int(module.main(args[1:]))
    ap = _parser()
    opts = ap.parse_args(args)
    if opts.print_name:
        return print_name(opts.input, opts.lang)
    dep_path = opts.depfile or (depfile.default_name(opts.output) if opts.md else None)
    if dep_path and opts.output == "-":
        ap.error("a dependency file (-MD, -MF) needs an output file (-o FILE)")
    apply_maxima_options(opts)
    for path in (opts.output, dep_path):  # before Maxima runs, as a compiler would fail at once
        if path and path != "-":
            require_folder(path)
    from .codegen.generate import generate, load
    from .languages import LANGUAGES

    try:
        spec, poly = load(opts.input, opts.timeout)
        out_name = "<stdout>" if opts.output == "-" else opts.output
        result = generate(spec, poly, LANGUAGES[opts.lang], opts.emit, out_name,
                          opts.strategy, not opts.no_variants)
        dep_text = None
        if dep_path:  # before any output is written: a path it cannot express is an error
            targets = [opts.output, *(path for path, _ in result.companions)]
            deps = [opts.input, *depfile.loaded_files(spec.program.statements)]
            dep_text = depfile.text(targets, deps, opts.mp)
        for line in shown(result.warnings, opts.quiet):
            print(line, file=sys.stderr)
        for path, text in result.companions:  # first: a definition precedes its implementation
            write_if_changed(path, text)
        write_if_changed(opts.output, result.text)
        if dep_path and dep_text is not None:
            write_if_changed(dep_path, dep_text)
    except Max2CodeError as exc:
        return report(exc)
    return 0
