"""C (C11): `#line` directives, `pow` from <math.h>, and C's keywords avoided."""

from __future__ import annotations

from dataclasses import dataclass

from ..diagnostics import Pos
from .base import Language

C_KEYWORDS = frozenset("""
auto break case char const continue default do double else enum extern float for goto if inline
int long register restrict return short signed sizeof static struct switch typedef union unsigned
void volatile while _Alignas _Alignof _Atomic _Bool _Complex _Generic _Imaginary _Noreturn
_Static_assert _Thread_local bool true false NULL main
sin cos tan sqrt exp log pow fabs atan atan2 asin acos sinh cosh tanh floor ceil fmod
""".split())


def c_string(text: str) -> str:
    """A C string literal (as `#line` takes it) holding exactly the bytes of `text`: quotes and
    backslashes escaped, `?` as `\\?` (no trigraph under -std=c11), every other byte outside
    printable ASCII as an octal escape (a file name's undecodable bytes come back as they were)."""
    out = ['"']
    for byte in text.encode("utf-8", "surrogateescape"):
        ch = chr(byte)
        if ch in '\\"?':
            out.append("\\" + ch)
        elif 0x20 <= byte < 0x7F:
            out.append(ch)
        else:
            out.append(f"\\{byte:03o}")
    return "".join(out) + '"'


@dataclass(frozen=True)
class C(Language):
    name: str = "c"
    extension: str = ".h"
    keywords: frozenset[str] = C_KEYWORDS
    functions: tuple[tuple[str, str], ...] = (
        ("sin", "sin"), ("cos", "cos"), ("tan", "tan"), ("sqrt", "sqrt"), ("exp", "exp"),
        ("log", "log"), ("abs", "fabs"), ("atan", "atan"), ("atan2", "atan2"),
        ("asin", "asin"), ("acos", "acos"), ("sinh", "sinh"), ("cosh", "cosh"), ("tanh", "tanh"),
    )

    # No wrapping: a `#line` directive numbers the lines after it, so a statement continued on
    # more lines would claim .mxm lines past the equation.
    max_line: int = 1 << 30

    def power_call(self, base: str, exponent: str) -> str:
        return f"pow({base}, {exponent})"

    def line_directive(self, pos: Pos) -> str:
        return f"#line {pos.line} {c_string(pos.file)}"

    def resume_directive(self, line: int, file: str) -> str | None:
        return f"#line {line} {c_string(file)}"

    def comment_text(self, text: str) -> str:
        """Inside /* */: nothing may close the comment, or open one (gcc -Wcomment)."""
        return super().comment_text(text).replace("*/", "*\\/").replace("/*", "/\\*")
