"""One .mxm to one output text: the whole pipeline, as the CLI and the build command use it."""

from __future__ import annotations

from dataclasses import dataclass

from ..maxima import session as maxima
from ..diagnostics import Diagnostic, error
from .emit import render
from ..languages import LANGUAGES, Language
from ..front.parse import parse_file
from .poly import Polynomial, check_declared_terms, polynomial
from ..front.spec import Spec
from .variants import DEFAULT_STRATEGY


@dataclass(frozen=True)
class Generated:
    spec: Spec
    poly: Polynomial
    text: str
    form: str
    warnings: tuple[Diagnostic, ...]
    # Files written beside the output, as (path, text); e.g. a Modula-2 NAME.def beside NAME.mod.
    companions: tuple[tuple[str, str], ...] = ()


def check_tags(spec: Spec) -> None:
    """Language tags on code blocks must name a registered language."""
    for block in spec.language_tags():
        if block.lang not in LANGUAGES:
            raise error(block.pos, f"unknown language tag '{block.lang}' (known: "
                        f"{', '.join(sorted(LANGUAGES))})")


def choose_form(spec: Spec, form: str) -> str:
    """`auto` gives the paper's fragment when the file has term blocks, else a module."""
    if form != "auto":
        return form
    return "fragment" if spec.terms else "module"


def load(path: str, timeout: float = maxima.DEFAULT_TIMEOUT) -> tuple[Spec, Polynomial]:
    spec = parse_file(path)
    check_tags(spec)
    return spec, polynomial(spec, timeout)


def generate(spec: Spec, poly: Polynomial, lang: Language, form: str, out_name: str,
             strategy: str = DEFAULT_STRATEGY, with_variants: bool = True) -> Generated:
    form = choose_form(spec, form)
    warnings = list(poly.warnings)
    mismatch = check_declared_terms(spec, poly, "error" if form == "fragment" else "warning")
    if mismatch is not None:
        if mismatch.severity == "error":
            raise error(mismatch.pos, mismatch.message)
        warnings.append(mismatch)
    out = render(spec, poly, lang, form, out_name, strategy, with_variants)
    return Generated(spec, poly, out.text, form, tuple(warnings) + out.warnings, out.companions)
