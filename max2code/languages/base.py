"""What every language printer shares: precedence-driven printing of expression trees.

A language subclasses `Language` and states its rules (literals, powers, functions, keywords,
line directives, terminators); the templates hold the layout. Nothing here names a language.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from fractions import Fraction
from functools import cached_property

from ..diagnostics import Pos, visible
from ..codegen.expr import Add, Call, Div, Expr, Float, Mul, Neg, Num, Pow, Ref, Sym

# Binding strength, loosest first.
P_ADD, P_MUL, P_NEG, P_POW, P_ATOM = 1, 2, 3, 4, 5

CONSTANT_VALUES = {"%pi": math.pi, "%e": math.e}


def _digits(value: Fraction) -> str:
    """A huge rational, shortly: its leading digits and its number of digits."""
    text = str(abs(value.numerator) // value.denominator)
    sign = "-" if value < 0 else ""
    return f"{sign}{text[0]}.{text[1:4]}e+{len(text) - 1}"


@dataclass(frozen=True)
class Language:
    """A target language's printing rules. Subclasses override the hooks below."""

    name: str = ""
    # The language's name in messages ("Modula-2").
    title: str = ""
    extension: str = ""
    # Words the language itself reserves: never an identifier, in any scope. A fragment (pasted
    # into the user's code) renames only these; see codegen/names.py.
    keywords: frozenset[str] = frozenset()
    # Names a generated module's code can see where it binds the user's names: library
    # modules and macros, builtins, preludes, pervasive identifiers, functions the printer calls.
    predeclared: frozenset[str] = frozenset()
    # A regular expression (matched at the start) for families of reserved names: our own
    # `m2c_` prefix, the C library's macro families. `{module}` stands for the module's name.
    reserved_pattern: str = ""
    # What an identifier of the language looks like.
    ident_pattern: str = r"[A-Za-z_][A-Za-z0-9_]*"
    # Whether a module shows the parameters' identifiers to its users (as the fields of a
    # struct or record), so that renaming one deserves a warning.
    shows_names: bool = True
    # Largest integer exponent written as repeated multiplication.
    max_inline_power: int = 8
    functions: tuple[tuple[str, str], ...] = ()
    terminator: str = ";"
    # How generated straight-line code names its temporaries, and how a variant's condition
    # (all of some parameters exactly zero) is written.
    temp_prefix: str = "m2c_t"
    and_op: str = " && "
    zero_test: str = "{} == 0.0"
    # Files the module form writes beside its output, as (extension, template stem) pairs:
    # e.g. a definition module beside an implementation module. Rendered from the same context.
    companions: tuple[tuple[str, str], ...] = ()

    # ---- hooks a language overrides -------------------------------------------------------
    def float_literal(self, value: float) -> str:
        text = repr(float(value))
        if text in ("inf", "-inf", "nan"):
            raise ValueError(f"non-finite constant {text} in an expression")
        return text if any(ch in text for ch in ".e") else text + ".0"

    def power_call(self, base: str, exponent: str) -> str:
        raise NotImplementedError

    def line_directive(self, pos: Pos) -> str:
        """A line that points a debugger (or a reader) at `pos` in the .mxm source."""
        raise NotImplementedError

    def resume_directive(self, line: int, file: str) -> str | None:
        """A line saying the next line is `line` of the generated `file`; None if not needed."""
        return None

    def comment_text(self, text: str) -> str:
        """`text` (a path, a name) made safe inside this language's comments: shown to a reader,
        never able to end the comment or the line. Templates use it as the `comment` filter."""
        return visible(text)

    # Generated lines longer than this are broken before a top-level + or -.
    max_line: int = 100

    def block_text(self, text: str) -> str:
        """An initialise or finalise block's code as the fragment holds it: as written, unless
        the language's own rules need otherwise (Python's indentation)."""
        return text

    def wrap(self, text: str, indent: int) -> str:
        """Break a long expression before its top-level additions, so that the expanded
        strategy's thousand-term coefficients stay readable (and line counts mean something)."""
        if len(text) + indent <= self.max_line:
            return text
        pieces, depth, start = [], 0, 0
        for i, ch in enumerate(text):
            depth += ch in "([{"
            depth -= ch in ")]}"
            if depth == 0 and i > start and text.startswith((" + ", " - "), i):
                pieces.append(text[start:i])
                start = i + 1
        pieces.append(text[start:])
        lines = [pieces[0]]
        for piece in pieces[1:]:
            if len(lines[-1]) + 1 + len(piece) + indent + 4 > self.max_line:
                lines.append(piece)
            else:
                lines[-1] += " " + piece
        return self.join_lines(lines, indent)

    def join_lines(self, lines: list[str], indent: int) -> str:
        """How a wrapped expression continues on the next line (free-form languages: as is)."""
        return ("\n" + " " * (indent + 4)).join(lines)

    def condition(self, idents: list[str]) -> str:
        return self.and_op.join(self.zero_test.format(i) for i in idents)

    # Parameter name -> identifier, for printing (codegen/names.py decides; empty: names as they are).
    names: tuple[tuple[str, str], ...] = ()

    def generated(self, module: str) -> frozenset[str]:
        """The identifiers a module named `module` defines beyond `reserved_pattern`: its
        templates' constants, functions and types. A user's name must not be one of them."""
        return frozenset()

    def module_name_problem(self, module: str) -> str | None:
        """Why `module` cannot name a module in this language (None when it can)."""
        if module in self.keywords:
            return f"a {self.title} keyword"
        return None

    def reserved(self, ident: str, module: str | None) -> str | None:
        """Why `ident` cannot stand for a user's name: 'keyword', 'invalid', or (in a module,
        when `module` is given) 'predeclared', 'generated', 'pattern'. None when it can."""
        if not re.fullmatch(self.ident_pattern, ident):
            return "invalid"
        if ident in self.keywords:
            return "keyword"
        if module is None:
            return None
        if ident in self.predeclared:
            return "predeclared"
        if ident in self.generated(module):
            return "generated"
        if self.reserved_pattern and re.match(self.reserved_pattern.format(
                module=re.escape(module)), ident):
            return "pattern"
        return None

    def escape(self, ident: str, why: str) -> str:
        """A first try at another identifier for a reserved one (codegen/names.py makes it unique)."""
        if why in ("pattern", "invalid"):
            return "p" + ("" if ident.startswith("_") else "_") + ident
        return ident + "_"

    def with_names(self, names: dict[str, str]) -> "Language":
        """This language printing parameter `name` as `names[name]`."""
        from dataclasses import replace
        return replace(self, names=tuple(sorted(names.items())))

    @cached_property
    def _names(self) -> dict[str, str]:
        return dict(self.names)

    # ---- shared rules ---------------------------------------------------------------------
    def identifier(self, name: str) -> str:
        """How a parameter is written: as codegen/names.py decided, else its name (a `%` made `_`)."""
        return self._names.get(name) or name.replace("%", "_")

    def number(self, value: Fraction) -> str:
        try:
            if value.denominator == 1 or Fraction(float(value)) == value:  # exact as a double
                return self.float_literal(float(value))
            return f"({self.float_literal(float(value.numerator))}/{self.float_literal(float(value.denominator))})"
        except OverflowError:  # a ValueError is reported at the equation by codegen/emit.py
            raise ValueError(f"the constant {_digits(value)} does not fit in a double") from None

    def expr(self, e: Expr) -> str:
        return self._print(e)[0]

    def _print(self, e: Expr) -> tuple[str, int]:
        """Text and binding strength of `e`."""
        if isinstance(e, Num):
            text = self.number(abs(e.value))
            return ("-" + text, P_NEG) if e.value < 0 else (text, P_ATOM)
        if isinstance(e, Float):
            text = self.float_literal(abs(e.value))
            return ("-" + text, P_NEG) if e.value < 0 else (text, P_ATOM)
        if isinstance(e, Ref):
            return e.name, P_ATOM
        if isinstance(e, Sym):
            if e.name in CONSTANT_VALUES:
                return self.float_literal(CONSTANT_VALUES[e.name]), P_ATOM
            return self.identifier(e.name), P_ATOM
        if isinstance(e, Neg):
            # Negation is exact, so -(a*b) may print as -a*b: a sign never changes a rounding.
            inner = self._wrap(e.arg, P_NEG + 1 if isinstance(e.arg, Neg) else P_MUL)
            return "-" + (f"({inner})" if inner.startswith("-") else inner), P_NEG
        if isinstance(e, Add):
            parts = [self._wrap(e.args[0], P_ADD)]
            for arg in e.args[1:]:
                if isinstance(arg, Neg):
                    parts.append(" - " + self._wrap(arg.arg, P_ADD + 1))
                elif isinstance(arg, Num) and arg.value < 0:
                    parts.append(" - " + self.number(-arg.value))
                else:
                    parts.append(" + " + self._wrap(arg, P_ADD))
            return "".join(parts), P_ADD
        if isinstance(e, Mul):
            return self._mul(e)
        if isinstance(e, Div):
            return f"{self._wrap(e.num, P_MUL)}/{self._wrap(e.den, P_MUL + 1)}", P_MUL
        if isinstance(e, Pow):
            return self._pow(e)
        if isinstance(e, Call):
            return self._call(e), P_ATOM
        raise TypeError(f"cannot print {e!r}")

    def _wrap(self, e: Expr, at_least: int) -> str:
        text, prec = self._print(e)
        return text if prec >= at_least else f"({text})"

    def _mul(self, e: Mul) -> tuple[str, int]:
        """Signs are pulled to the front so `a*(-b)` prints as `-(a*b)`'s plain form `-a*b`."""
        negative = False
        factors: list[Expr] = []
        for f in e.args:
            if isinstance(f, Neg):
                negative, f = not negative, f.arg
            elif isinstance(f, Num) and f.value < 0:
                negative, f = not negative, Num(-f.value)
            if isinstance(f, Num) and f.value == 1:
                continue
            factors.append(f)
        if not factors:
            text, prec = self.number(Fraction(1)), P_ATOM
        else:
            text = "*".join(self._wrap(f, P_MUL if i == 0 else P_MUL + 1) for i, f in enumerate(factors))
            prec = P_MUL if len(factors) > 1 else self._print(factors[0])[1]
        if negative:
            return "-" + (text if prec >= P_MUL and not text.startswith("-") else f"({text})"), P_NEG
        return text, prec

    def _pow(self, e: Pow) -> tuple[str, int]:
        exp = e.exp
        if isinstance(exp, Num) and exp.value.denominator == 1:
            n = exp.value.numerator
            if n == 0:
                return self.number(Fraction(1)), P_ATOM
            if 1 <= abs(n) <= self.max_inline_power:
                base = self._wrap(e.base, P_ATOM)
                text = "*".join([base] * abs(n))
                if n > 0:
                    return text, (P_MUL if n > 1 else P_ATOM)
                return f"{self.number(Fraction(1))}/{text if n == -1 else f'({text})'}", P_MUL
        if isinstance(exp, Num) and exp.value == Fraction(1, 2):
            return self._call(Call("sqrt", (e.base,))), P_ATOM
        return self.power_call(self.expr(e.base), self.expr(exp)), P_ATOM

    def _call(self, e: Call) -> str:
        names = dict(self.functions)
        if e.name not in names:
            raise ValueError(f"function '{e.name}' has no equivalent in {self.name}")
        return f"{names[e.name]}({', '.join(self.expr(a) for a in e.args)})"
