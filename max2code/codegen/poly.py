"""From a Spec to a Polynomial in the equation's variable, with every coefficient asked of Maxima.

We ask Maxima for `coeff(expand(e), t, k)` for each power, check that the result really is a
polynomial in `t` (nothing of `t` in a denominator, inside a function, or left in a coefficient),
and let absent powers be 0. The original tool parsed the printed sum instead and got the orbiting
circles wrong.
"""

from __future__ import annotations

import itertools
import re
from dataclasses import dataclass, replace

from ..maxima import session as maxima
from ..diagnostics import Diagnostic, Max2CodeError, Pos, error
from .expr import ZERO, Expr, ExprSyntaxError, calls, parse_maxima, symbols
from ..front.spec import Spec

CONSTANTS = frozenset({"%pi", "%e"})
E = "m2c__e"
# Every subset of the roles is derived: 2^MAX_ROLES variants at most.
MAX_ROLES = 10


@dataclass(frozen=True)
class Polynomial:
    """Coefficients of one equation: `coefficients[k]` multiplies `variable**k`."""

    variable: str
    coefficients: tuple[Expr, ...]
    parameters: tuple[str, ...]
    maxima_seconds: float
    # Lines Maxima prints for the equation at its default width (79): as the program left
    # it, and as the expanded polynomial (sum of its coefficient texts); for the report.
    maxima_lines: int
    warnings: tuple[Diagnostic, ...] = ()
    # Maxima's simplified but unexpanded equation: what the optimised strategy works from.
    unexpanded: Expr | None = None
    maxima_lines_expanded: int = 0
    # For a variant: the roles and parameters that are zero; for the general one: ().
    roles: tuple[str, ...] = ()
    zeros: tuple[str, ...] = ()
    variants: tuple[Polynomial, ...] = ()

    @property
    def degree(self) -> int:
        return len(self.coefficients) - 1


def extraction_script(variable: str,
                      variants: tuple[tuple[str, ...], ...] = ((),)) -> str:
    """Maxima code run after the user's program: `%` holds the equation.

    Noun forms are evaluated (`ev(.., nouns)`) because the paper's figures quote their Taylor
    helper (`'O(...)`) and rely on it being expanded later; an equation `l = r` becomes `l - r`.
    Each entry of `variants` names parameters set to zero (the first is normally none); every
    variant is reported between VARIANT and END markers, in the same session.
    """
    t = variable
    m = maxima.MARK
    zero_lists = ", ".join("[" + ", ".join(f"{p} = 0" for p in zeros) + "]" for zeros in variants)
    return "\n".join([
        f"{E}: %$",
        f"{E}: ev({E}, nouns)$",
        f'{E}: if not atom({E}) and op({E}) = "=" then lhs({E}) - rhs({E}) else {E}$',
        maxima.marker("EXTRACT"),
        "m2c__report(m2c__i, m2c__v) := block([m2c__x, m2c__n],",
        f'  printf(true, "~%{m}-VARIANT ~d~%", m2c__i),',
        f'  printf(true, "~%{m}-KIND ~a~%", if stringp(m2c__v) then "a string" '
        f'elseif listp(m2c__v) then "a list" elseif matrixp(m2c__v) then "a matrix" '
        f'elseif not atom(m2c__v) and member(op(m2c__v), ["<", ">", "<=", ">=", "#", "and", "or"]) '
        f'then "a condition" else "expr"),',
        f'  printf(true, "~%{m}-SHOWN ~d~%", slength(string(m2c__v))),',
        f'  printf(true, "~%{m}-UNEXPANDED ~a~%", string(m2c__v)),',
        # Variants are substitutions into the general equation: its checks cover them.
        f'  printf(true, "~%{m}-DENOM ~a~%", if m2c__i > 0 or freeof({t}, denom(ratsimp(m2c__v))) '
        f"then 0 else 1),",
        # expand() leaves powers above maxposex (1000) alone: (t - 1)^2000 would look like
        # a coefficient holding t. Any whole power is expanded here.
        "  m2c__x: expand(m2c__v, 1000000, 1000000),",
        f"  m2c__n: hipow(m2c__x, {t}),",
        f'  for m2c__k: 0 thru m2c__n do printf(true, "~%{m}-COEF ~d ~a~%", m2c__k, '
        f"string(coeff(m2c__x, {t}, m2c__k))),",
        f'  printf(true, "~%{m}-REST ~a~%", if m2c__i > 0 then 0 else string(expand(m2c__x - '
        f"sum(coeff(m2c__x, {t}, m2c__k) * {t}^m2c__k, m2c__k, 0, m2c__n)))),",
        f'  printf(true, "~%{m}-VARIANT-END ~d~%", m2c__i))$',
        f"m2c__zeros: [{zero_lists}]$",
        f"for m2c__i: 1 thru length(m2c__zeros) do m2c__report(m2c__i - 1, "
        f"subst(m2c__zeros[m2c__i], {E}))$",
        maxima.marker("END"),
    ]) + "\n"


def polynomial(spec: Spec, timeout: float = maxima.DEFAULT_TIMEOUT,
               combos: list[tuple[tuple[str, ...], tuple[str, ...]]] | None = None) -> Polynomial:
    """The equation's polynomial, with one specialised variant per combination of its roles
    (or per entry of `combos`: (names, parameters set to zero), the first being ((), ()))."""
    statements = spec.program.statements
    where = spec.program.last_pos
    if not statements:
        raise error(spec.program.pos, "the Maxima program is empty: it must end with the equation")
    combos = role_combinations(spec) if combos is None else combos
    script = maxima.program_script(statements, spec.own_names) + extraction_script(
        spec.variable, tuple(zeros for _, zeros in combos))
    session = maxima.run(script, statements, where, timeout)
    text = session.output
    if not _field(text, "END"):
        raise error(where, "Maxima stopped before the coefficients were read (no error message "
                    "was recognised; run the program in Maxima to see why)")
    blocks = re.findall(rf"^{maxima.MARK}-VARIANT (\d+)$([\s\S]*?)^{maxima.MARK}-VARIANT-END \1$",
                        text, re.M)
    if not blocks or blocks[0][0] != "0":
        raise error(where, "Maxima stopped before the coefficients were read")
    general = _read(spec, blocks[0][1], where, spec.variable)
    params = _parameters(spec, general.coefficients)
    for role in spec.roles:
        unknown = [p for p in role.params if p not in params]
        if unknown:
            raise error(role.pos, f"role '{role.name}' names {', '.join(unknown)}, not a parameter "
                        f"of the equation")
    variants = []
    bodies = {int(index): body for index, body in blocks}
    for index, (roles, zeros) in enumerate(combos[1:], start=1):
        if index not in bodies:
            continue
        try:
            v = _read(spec, bodies[index], where, spec.variable)
        except Max2CodeError:
            continue  # e.g. everything vanishes: that combination is no variant
        variants.append(replace(v, parameters=params, roles=roles, zeros=zeros))
    return replace(general, parameters=params, maxima_seconds=session.seconds,
                   warnings=_warnings(spec, params), variants=tuple(variants))


def role_combinations(spec: Spec) -> list[tuple[tuple[str, ...], tuple[str, ...]]]:
    """Every subset of the declared roles, as (role names, parameters set to zero); the empty
    subset (the general equation) first."""
    out: list[tuple[tuple[str, ...], tuple[str, ...]]] = [((), ())]
    roles = spec.roles
    if len(roles) > MAX_ROLES:
        raise error(roles[MAX_ROLES].pos, f"more than {MAX_ROLES} roles: {2 ** len(roles)} "
                    f"combinations are too many to derive; group parameters into fewer roles")
    for size in range(1, len(roles) + 1):
        for combo in itertools.combinations(roles, size):
            zeros = tuple(sorted({p for r in combo for p in r.params}))
            out.append((tuple(r.name for r in combo), zeros))
    return out


def _field(text: str, tag: str) -> list[str]:
    return re.findall(rf"^{maxima.MARK}-{tag} (.*)$", text, re.M)


def _read(spec: Spec, text: str, where: Pos, t: str) -> Polynomial:
    kind = _field(text, "KIND")[0]
    if kind != "expr":
        raise error(where, f"the program's last result is {kind}, not a polynomial equation in {t}")
    if _field(text, "DENOM")[0].strip() != "0":
        raise error(where, f"not a polynomial: the variable '{t}' appears in a denominator")
    coefficients = []
    expanded_chars = 0
    try:
        for raw in _field(text, "COEF"):
            body = raw.split(" ", 1)[1]
            expanded_chars += len(body) + 8  # and "*t^k+" between terms
            coefficients.append(parse_maxima(body))
        unexpanded = parse_maxima(_field(text, "UNEXPANDED")[0])
    except ExprSyntaxError as exc:
        raise error(where, str(exc)) from None
    rest = _field(text, "REST")[0].strip()
    if not _zero(rest) or any(t in symbols(c) for c in coefficients):
        raise error(where, f"not a polynomial in '{t}': '{t}' is left inside a function or a "
                    f"non-integer power ({_inside(coefficients, rest, t)})")
    while len(coefficients) > 1 and coefficients[-1] == ZERO:
        coefficients.pop()
    if all(c == ZERO for c in coefficients):
        raise error(where, f"the equation is identically zero: no polynomial in '{t}' to solve")
    if len(coefficients) == 1:
        raise error(where, f"the equation does not depend on '{t}' (degree 0): nothing to solve")
    shown = int(_field(text, "SHOWN")[0])
    return Polynomial(t, tuple(coefficients), (), 0.0, maxima_lines=max(1, -(-shown // 79)),
                      unexpanded=unexpanded, maxima_lines_expanded=max(1, -(-expanded_chars // 79)))


def _zero(text: str) -> bool:
    """Maxima's printed remainder is zero: 0, or 0.0 (or a bigfloat 0.0b0) where the equation
    has decimal constants -- the subtraction of the terms from themselves in floating point."""
    if text == "0":
        return True
    try:
        return float(text.replace("b", "e")) == 0.0
    except ValueError:
        return False


def _inside(coefficients: list[Expr], rest: str, t: str) -> str:
    for c in coefficients:
        names = sorted(n for n in calls(c))
        if names and t in symbols(c):
            return f"for example inside {names[0]}(...)"
    return f"remainder {rest[:60]}" if not _zero(rest) else f"'{t}' remains in a coefficient"


def _parameters(spec: Spec, coefficients: list[Expr]) -> tuple[str, ...]:
    used: set[str] = set()
    for c in coefficients:
        used |= symbols(c)
    used -= CONSTANTS
    for c in coefficients:
        for name in sorted(calls(c)):
            raise error(spec.program.last_pos, f"the result calls '{name}(...)', which is not "
                        f"defined in the program; coefficients must be expressions in parameters")
    declared = spec.parameter_order
    if declared is None:
        return tuple(sorted(used))
    if spec.variable in declared:
        assert spec.parameters is not None
        raise error(spec.parameters.pos, f"'{spec.variable}' is the polynomial's variable, not a "
                    f"parameter: the coefficients are in the others (a parameter of that name "
                    f"would be ignored)")
    missing = sorted(used - set(declared))
    if missing:
        assert spec.parameters is not None
        hint = ""
        if {"true", "false"} & set(missing):
            hint = (" (true and false are values: a name Maxima gives one, such as a flag read "
                    "as a variable, leaves them in the equation)")
        raise error(spec.parameters.pos, f"the equation uses {', '.join(missing)}, not listed in "
                    f"'parameters'{hint}")
    return declared


def _warnings(spec: Spec, params: tuple[str, ...]) -> tuple[Diagnostic, ...]:
    """The original files name the coefficient array `a`, which is also a parameter there."""
    for term in spec.terms:
        for name in re.findall(r"\b([A-Za-z_]\w*)\s*\[", term.prefix.text):
            if name in params:
                return (Diagnostic(term.prefix.pos, f"the term prefixes index '{name}', which is "
                                   f"also a parameter of the equation", "warning"),)
    return ()


def check_declared_terms(spec: Spec, poly: Polynomial, severity: str = "error") -> Diagnostic | None:
    """`polynomial terms N` counts coefficients (degree + 1); say both numbers on a mismatch."""
    if spec.terms_declared is None:
        return None
    declared = int(spec.terms_declared.value)  # type: ignore[arg-type]
    have = poly.degree + 1
    if declared == have:
        return None
    return Diagnostic(spec.terms_declared.pos,
                      f"'polynomial terms {declared}' declares {declared} coefficients, but the "
                      f"equation has degree {poly.degree} ({have} coefficients, t^0..t^{poly.degree})",
                      severity)

