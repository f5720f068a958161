"""Which identifier each parameter gets in a language: the user's own name wherever it can be.

A module is our code. Its functions, constants and locals are generated identifiers, and the
language, its library and its macros predeclare more; a parameter keeps its name unless the
language reserves it there (`Language.reserved`), and then gets the language's escape (`int_`,
`r#type`, `p_m2c_x`). Where the module shows the name to its users (a struct or record field)
the renaming is a warning.

A fragment is pasted into the user's code, where their variables already have the names the
.mxm uses: only a keyword of the language is renamed (it could not be their variable's name),
with a warning, unless the language can write the keyword as a name (Rust's `r#type`).

Either way the chosen identifiers are distinct from each other, from every kept name and from
everything reserved, and the choice depends only on the parameters, in their order.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..diagnostics import Diagnostic, Pos
from ..languages.base import Language

REASONS = {
    "keyword": "a {title} keyword",
    "invalid": "not a {title} identifier",
    "predeclared": "predeclared in {title} code (a library, builtin or macro name)",
    "generated": "a name the generated {title} module defines",
    "pattern": "reserved in {title} (the library's or the generated code's own names)",
}


@dataclass(frozen=True)
class Naming:
    """Parameter name -> identifier, and the renamings worth telling the user about."""

    idents: dict[str, str]
    warnings: tuple[Diagnostic, ...] = ()


def _base(name: str) -> str:
    return name.replace("%", "_")


def choose(params: tuple[str, ...], lang: Language, module: str | None,
           where: Pos) -> Naming:
    """Identifiers for `params` in a module named `module`, or in a fragment (`module` None)."""
    reasons = {p: lang.reserved(_base(p), module) for p in params}
    idents: dict[str, str] = {}
    taken: set[str] = set()
    for p in params:  # names that need no change keep them, first come first served
        if reasons[p] is None and _base(p) not in taken:
            idents[p] = _base(p)
            taken.add(_base(p))
    warnings = []
    for p in params:
        if p in idents:
            continue
        why = reasons[p] or "duplicate"
        first = _base(p) if why == "duplicate" else lang.escape(_base(p), why)
        ident = first
        for k in range(2, 1000):
            problem = lang.reserved(ident, module)
            if problem in ("pattern", "invalid"):
                ident = first = lang.escape(ident, problem)
                continue
            if problem is None and ident not in taken:
                break
            ident = f"{first.rstrip('_')}_{k}"  # never `__`, which C reserves
        else:  # pragma: no cover - every escape ends in an ordinary name within a few steps
            raise AssertionError(f"no identifier for {p!r} in {lang.name}")
        idents[p] = ident
        taken.add(ident)
        raw = ident.removeprefix("r#") == _base(p)  # Rust writes the keyword itself
        if (module is None or lang.shows_names) and not raw:
            reason = (f"'{p}' is also the name of another parameter there" if why == "duplicate"
                      else f"'{_base(p)}' is " + REASONS[why].format(title=lang.title))
            form = "module" if module is not None else "fragment"
            warnings.append(Diagnostic(where, f"parameter '{p}' is written '{ident}' in the "
                                       f"{lang.title} {form}: {reason}", "warning"))
    return Naming({p: idents[p] for p in params}, tuple(warnings))
