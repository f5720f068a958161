"""Modula-2 (ISO, as GNU Modula-2 compiles it): `#line` for gm2 -fcpp, REAL literals, signs.

Three Modula-2 rules shape the printing:

* A real literal needs a digit on both sides of the point and an upper-case scale factor:
  `2.0`, `1.0E-05`.
* A sign may only begin a simple expression: `a*-b` and `a + -b` are syntax errors, so a signed
  operand is parenthesised (`a*(-b)`) and a signed addend becomes a subtraction (`a - b`).
* gm2 12 with `-fcpp` maps `#line N` to line N-1 (gcc maps it to N), and without a directive of
  ours it numbers the whole preprocessed file one line low as well. Every directive is therefore
  written as N+1, so gdb and DWARF land on line N. (Measured with `objdump --dwarf=decodedline`
  and gdb; tests/test_line_directives.py checks it.)

REAL, not LONGREAL: in gm2 on x86-64 SIZE(REAL) = 8 is C's double and SIZE(LONGREAL) = 16 is
C's long double, so REAL is the type that matches the C runtime and the other three languages.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

from ...diagnostics import Pos
from ..base import Language
from ..c.printer import c_string
from ..signed import SignedOperands

# Reserved words of ISO Modula-2 and GNU Modula-2 (case-sensitive: `TYPE` is a keyword, `type`
# is an ordinary name).
M2_KEYWORDS = frozenset("""
AND ARRAY BEGIN BY CASE CONST DEFINITION DIV DO ELSE ELSIF END EXCEPT EXIT EXPORT FINALLY FOR
FORWARD FROM IF IMPLEMENTATION IMPORT IN LOOP MOD MODULE NOT OF OR PACKEDSET POINTER PROCEDURE
QUALIFIED RECORD REM REPEAT RETRY RETURN SET THEN TO TYPE UNTIL VAR WHILE WITH UNQUALIFIED ASM
VOLATILE
""".split())

# Pervasive identifiers (ISO and GNU), the library modules and procedures the generated module
# imports (a local of that name would hide what the module's code uses), and the macros the C
# preprocessor of `gm2 -fcpp` predefines (`linux` would become 1).
M2_PREDECLARED = frozenset("""
ABS BITSET BOOLEAN CAP CARDINAL CHAR CHR CMPLX COMPLEX DEC DISPOSE EXCL FALSE FLOAT HALT HIGH
IM INC INCL INT INTEGER INTERRUPTIBLE LENGTH LFLOAT LONGCOMPLEX LONGREAL MAX MIN NEW NIL ODD ORD
PROC PROTECTION RE REAL SIZE TRUE TRUNC UNINTERRUPTIBLE VAL LONGINT LONGCARD SHORTINT SHORTCARD
SHORTREAL SHORTCOMPLEX LOC BYTE WORD ADDRESS ADR TSIZE SYSTEM CAST THROW M2RTS
RealMath Strings Max2codeRoots STextIO SWholeIO SRealIO
linux unix i386 i686 sparc mips vax
""".split())

# The module's own names (module.j2, definition.j2), beyond the `m2c_` prefix.
M2_GENERATED = frozenset("""
NParams Degree NVariants Coefficients FirstRoot Variant VariantName ParamName Params
ParamsArray CoefficientsNamed FirstRootNamed VariantNamed
""".split())

# The formal parameters and locals of the exported procedures, which bind no parameter (the
# ones that do are CoefficientsVk and m2c_variant, with `m2c_` formals): a parameter may keep
# such a name, and Params may have a field `c`.
M2_FORMALS = frozenset("p c t tmax name i q degree".split())


@dataclass(frozen=True)
class Modula2(SignedOperands):
    name: str = "m2"
    title: str = "Modula-2"
    extension: str = ".mod"
    keywords: frozenset[str] = M2_KEYWORDS
    predeclared: frozenset[str] = M2_PREDECLARED
    reserved_pattern: str = r"(?i:m2c)_|CoefficientsV[0-9]+$"
    # An identifier starts with a letter (gm2 accepts `_` after it).
    ident_pattern: str = r"[A-Za-z][A-Za-z0-9_]*"
    terminator: str = " ;"
    functions: tuple[tuple[str, str], ...] = (
        ("sin", "RealMath.sin"), ("cos", "RealMath.cos"), ("tan", "RealMath.tan"),
        ("sqrt", "RealMath.sqrt"), ("exp", "RealMath.exp"), ("log", "RealMath.ln"),
        ("abs", "ABS"), ("atan", "RealMath.arctan"), ("asin", "RealMath.arcsin"),
        ("acos", "RealMath.arccos"),
    )
    # The DEFINITION MODULE is written beside the IMPLEMENTATION MODULE: NAME.mod -> NAME.def.
    companions: tuple[tuple[str, str], ...] = ((".def", "definition"),)
    # A variant's condition: AND binds tighter than = in Modula-2, hence the parentheses.
    and_op: str = " AND "
    zero_test: str = "({} = 0.0)"
    # gm2 12 -fcpp puts `#line N` on line N-1; see the module docstring.
    line_offset: int = 1

    def float_literal(self, value: float) -> str:
        text = super().float_literal(value)
        mantissa, _, exponent = text.partition("e")
        if "." not in mantissa:
            mantissa += ".0"
        return mantissa + ("E" + exponent if exponent else "")

    def power_call(self, base: str, exponent: str) -> str:
        return f"RealMath.power({base}, {exponent})"

    def generated(self, module: str) -> frozenset[str]:
        return M2_GENERATED | {module}

    def module_name_problem(self, module: str) -> str | None:
        if module in self.keywords:
            return "a Modula-2 reserved word"
        if module in self.predeclared or module in M2_GENERATED:
            return "a name the module already uses (a pervasive identifier, a library module, " \
                   "or one of its own procedures and constants)"
        if not re.fullmatch(self.ident_pattern, module):
            return "not a Modula-2 identifier (it must begin with a letter)"
        return None

    def line_directive(self, pos: Pos) -> str:
        return f"#line {pos.line + self.line_offset} {c_string(pos.file)}"

    def resume_directive(self, line: int, file: str) -> str | None:
        return f"#line {line + self.line_offset} {c_string(file)}"

    def comment_text(self, text: str) -> str:
        """Inside (* *), which nest, and read by gm2 -fcpp's C preprocessor first: no comment
        of either language may open or close."""
        text = super().comment_text(text)
        for pair in ("(*", "*)", "/*", "*/", "//"):
            text = text.replace(pair, pair[0] + "\\" + pair[1])
        return text

    def wrap(self, text: str, indent: int) -> str:
        """Never wrapped: gm2 gives a continuation line its own line number, so a statement split
        over three lines after `#line N` would claim .mxm lines N, N+1 and N+2."""
        return text

    def needs_math(self, ctx: Any) -> bool:
        """Whether the module's code calls RealMath (so the template imports it)."""
        codes = [code for v in ctx.variants for _, code in v.temps]
        codes += [c.code for v in ctx.variants for c in v.coefficients]
        return any("RealMath." in code for code in codes)
