"""From a Spec to a Polynomial in the equation's variable, with every coefficient asked of Maxima.

We ask Maxima for `coeff(expand(e), t, k)` for each power, check that the result really is a
polynomial in `t` (nothing of `t` in a denominator, inside a function, or left in a coefficient),
and let absent powers be 0. The original tool parsed the printed sum instead and got the orbiting
circles wrong.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from . import maxima
from .diagnostics import Diagnostic, Pos, error
from .expr import ZERO, Expr, ExprSyntaxError, calls, parse_maxima, symbols
from .spec import Spec

CONSTANTS = frozenset({"%pi", "%e"})
E = "m2c__e"
X = "m2c__x"


@dataclass(frozen=True)
class Polynomial:
    """Coefficients of one equation: `coefficients[k]` multiplies `variable**k`."""

    variable: str
    coefficients: tuple[Expr, ...]
    parameters: tuple[str, ...]
    maxima_seconds: float
    maxima_lines: int
    warnings: tuple[Diagnostic, ...] = ()

    @property
    def degree(self) -> int:
        return len(self.coefficients) - 1


def extraction_script(variable: str, substitutions: tuple[tuple[str, str], ...] = ()) -> str:
    """Maxima code run after the user's program: `%` holds the equation.

    Noun forms are evaluated (`ev(.., nouns)`) because the paper's figures quote their Taylor
    helper (`'O(...)`) and rely on it being expanded later; an equation `l = r` becomes `l - r`.
    `substitutions` set parameters to values first (how variants are derived).
    """
    t = variable
    subst = ", ".join(f"{name} = {value}" for name, value in substitutions)
    lines = [
        f"{E}: %$",
        f"{E}: ev({E}, nouns)$",
        f'{E}: if not atom({E}) and op({E}) = "=" then lhs({E}) - rhs({E}) else {E}$',
        f"{E}: subst([{subst}], {E})$" if subst else "",
        maxima.marker("EXTRACT"),
        f'printf(true, "~%{maxima.MARK}-KIND ~a~%", if stringp({E}) then "a string" '
        f'elseif listp({E}) then "a list" elseif matrixp({E}) then "a matrix" '
        f'elseif not atom({E}) and member(op({E}), ["<", ">", "<=", ">=", "#", "and", "or"]) '
        f'then "a condition" else "expr")$',
        f'printf(true, "~%{maxima.MARK}-SHOWN ~d~%", slength(string({E})))$',
        f'printf(true, "~%{maxima.MARK}-DENOM ~a~%", if freeof({t}, denom(ratsimp({E}))) '
        f'then 0 else 1)$',
        f"{X}: expand({E})$",
        f"m2c__n: hipow({X}, {t})$",
        f'for m2c__k: 0 thru m2c__n do printf(true, "~%{maxima.MARK}-COEF ~d ~a~%", m2c__k, '
        f"string(coeff({X}, {t}, m2c__k)))$",
        f'printf(true, "~%{maxima.MARK}-REST ~a~%", string(expand({X} - sum(coeff({X}, {t}, m2c__k)'
        f" * {t}^m2c__k, m2c__k, 0, m2c__n))))$",
        maxima.marker("END"),
    ]
    return "\n".join(line for line in lines if line) + "\n"


def polynomial(spec: Spec, timeout: float = maxima.DEFAULT_TIMEOUT,
               substitutions: tuple[tuple[str, str], ...] = ()) -> Polynomial:
    statements = spec.program.statements
    where = spec.program.last_pos
    if not statements:
        raise error(spec.program.pos, "the Maxima program is empty: it must end with the equation")
    script = maxima.program_script(statements) + extraction_script(spec.variable, substitutions)
    session = maxima.run(script, statements, where, timeout)
    return _read(spec, session, where)


def _field(text: str, tag: str) -> list[str]:
    return re.findall(rf"^{maxima.MARK}-{tag} (.*)$", text, re.M)


def _read(spec: Spec, session: maxima.Session, where: Pos) -> Polynomial:
    text, t = session.output, spec.variable
    if not _field(text, "END"):
        raise error(where, "Maxima stopped before the coefficients were read (no error message "
                    "was recognised; run the program in Maxima to see why)")
    kind = _field(text, "KIND")[0]
    if kind != "expr":
        raise error(where, f"the program's last result is {kind}, not a polynomial equation in {t}")
    if _field(text, "DENOM")[0].strip() != "0":
        raise error(where, f"not a polynomial: the variable '{t}' appears in a denominator")
    coefficients = []
    for raw in _field(text, "COEF"):
        _, body = raw.split(" ", 1)
        try:
            coefficients.append(parse_maxima(body))
        except ExprSyntaxError as exc:
            raise error(where, str(exc)) from None
    rest = _field(text, "REST")[0].strip()
    if rest != "0" or any(t in symbols(c) for c in coefficients):
        raise error(where, f"not a polynomial in '{t}': '{t}' is left inside a function or a "
                        f"non-integer power ({_inside(coefficients, rest, t)})")
    while len(coefficients) > 1 and coefficients[-1] == ZERO:
        coefficients.pop()
    if all(c == ZERO for c in coefficients):
        raise error(where, f"the equation is identically zero: no polynomial in '{t}' to solve")
    if len(coefficients) == 1:
        raise error(where, f"the equation does not depend on '{t}' (degree 0): nothing to solve")
    params = _parameters(spec, coefficients)
    shown = int(_field(text, "SHOWN")[0])
    return Polynomial(t, tuple(coefficients), params, session.seconds,
                      maxima_lines=max(1, -(-shown // 79)), warnings=_warnings(spec, params))


def _inside(coefficients: list[Expr], rest: str, t: str) -> str:
    for c in coefficients:
        names = sorted(n for n in calls(c))
        if names and t in symbols(c):
            return f"for example inside {names[0]}(...)"
    return f"remainder {rest[:60]}" if rest != "0" else f"'{t}' remains in a coefficient"


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
    missing = sorted(used - set(declared))
    if missing:
        assert spec.parameters is not None
        raise error(spec.parameters.pos, f"the equation uses {', '.join(missing)}, not listed in "
                    f"'parameters'")
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

