"""Rust (2021 edition): `// file.mxm:LINE` comments, `f64` methods, keywords avoided.

Generated Rust must build without warnings and pass `cargo clippy -- -D warnings`:
* exact constants (`%pi`, and any float equal to one of `std::f64::consts`) are written by name,
  because clippy's `approx_constant` rejects a literal 3.141592653589793;
* parameter names that are not snake_case (`TYPE`, `X1`) would trip `non_snake_case`; renaming
  them could collide (`type` and `TYPE`), so the template allows that one lint on the function
  that binds them, and only when a name needs it (`lint_allows`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..diagnostics import Pos
from .m2 import SignedOperands

# Strict, reserved and weak keywords (all editions), names that cannot even be raw identifiers
# (self, Self, super, crate), and the names the generated module itself defines or uses.
RUST_KEYWORDS = frozenset("""
as break const continue crate else enum extern false fn for if impl in let loop match mod move
mut pub ref return self Self static struct super trait true type unsafe use where while async
await dyn abstract become box do final macro override priv typeof unsized virtual yield try
union gen macro_rules raw safe
f32 f64 i8 i16 i32 i64 i128 isize u8 u16 u32 u64 u128 usize bool char str std core alloc
p NAME PARAMS DEGREE STRATEGY VARIANTS coefficients coefficients_degree first_root variant
max2code_runtime
""".split())

# Values clippy's `approx_constant` knows, by the name Rust gives them.
F64_CONSTS = (
    "E", "FRAC_1_PI", "FRAC_1_SQRT_2", "FRAC_2_PI", "FRAC_2_SQRT_PI", "FRAC_PI_2", "FRAC_PI_3",
    "FRAC_PI_4", "FRAC_PI_6", "FRAC_PI_8", "LN_10", "LN_2", "LOG10_E", "LOG2_E", "LOG2_10",
    "LOG10_2", "PI", "SQRT_2", "TAU",
)
_CONST_VALUES = {
    "E": math.e, "FRAC_1_PI": 1 / math.pi, "FRAC_1_SQRT_2": 1 / math.sqrt(2),
    "FRAC_2_PI": 2 / math.pi, "FRAC_2_SQRT_PI": 2 / math.sqrt(math.pi), "FRAC_PI_2": math.pi / 2,
    "FRAC_PI_3": math.pi / 3, "FRAC_PI_4": math.pi / 4, "FRAC_PI_6": math.pi / 6,
    "FRAC_PI_8": math.pi / 8, "LN_10": math.log(10), "LN_2": math.log(2),
    "LOG10_E": math.log10(math.e), "LOG2_E": math.log2(math.e), "LOG2_10": math.log2(10),
    "LOG10_2": math.log10(2), "PI": math.pi, "SQRT_2": math.sqrt(2), "TAU": math.tau,
}
assert set(_CONST_VALUES) == set(F64_CONSTS)


def is_snake_case(ident: str) -> bool:
    """rustc's test for the `non_snake_case` lint: no upper case, no `__` inside."""
    core = ident.strip("_")
    return not any(ch.isupper() for ch in core) and "__" not in core


@dataclass(frozen=True)
class Rust(SignedOperands):
    name: str = "rust"
    extension: str = ".rs"
    keywords: frozenset[str] = RUST_KEYWORDS
    # Rust's maths are f64 methods, written as paths (`f64::sin(x)`) so any argument text works.
    functions: tuple[tuple[str, str], ...] = tuple((m, f"f64::{r}") for m, r in (
        ("sin", "sin"), ("cos", "cos"), ("tan", "tan"), ("sqrt", "sqrt"), ("exp", "exp"),
        ("log", "ln"), ("abs", "abs"), ("atan", "atan"), ("atan2", "atan2"), ("asin", "asin"),
        ("acos", "acos"), ("sinh", "sinh"), ("cosh", "cosh"), ("tanh", "tanh")))

    def float_literal(self, value: float) -> str:
        for name, const in _CONST_VALUES.items():
            if float(value) == const:
                return f"std::f64::consts::{name}"
        return super().float_literal(value)

    def power_call(self, base: str, exponent: str) -> str:
        return f"f64::powf({base}, {exponent})"

    def line_directive(self, pos: Pos) -> str:
        return f"// {self.comment_text(pos.file)}:{pos.line}"

    def lint_allows(self, idents: list[str]) -> str:
        """An `#[allow(...)]` line for a function binding these names, or '' if none is needed."""
        if all(is_snake_case(i) for i in idents):
            return ""
        return "#[allow(non_snake_case)] // parameter names as the .mxm spells them"
