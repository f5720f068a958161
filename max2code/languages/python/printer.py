"""Python: `# file.mxm:LINE` comments instead of line directives, `math` functions."""

from __future__ import annotations

import textwrap

from dataclasses import dataclass

from ...diagnostics import Pos
from ...codegen.expr import Add, Expr
from ..base import P_ATOM, Language

# Python's hard keywords (soft ones, `match`, `case`, `type`, `_`, are ordinary names). Written
# out rather than read from `keyword`, so that the output does not depend on the Python running.
PY_KEYWORDS = frozenset("""
False None True and as assert async await break class continue def del elif else except finally
for from global if import in is lambda nonlocal not or pass raise return try while with yield
""".split())

# The builtins (Python 3.13's; tests/test_names.py checks the running Python has no others),
# and the modules (and names) the generated code imports.
PY_PREDECLARED = frozenset("""
ArithmeticError AssertionError AttributeError BaseException BaseExceptionGroup BlockingIOError
BrokenPipeError BufferError BytesWarning ChildProcessError ConnectionAbortedError ConnectionError
ConnectionRefusedError ConnectionResetError DeprecationWarning EOFError Ellipsis EncodingWarning
EnvironmentError Exception ExceptionGroup False FileExistsError FileNotFoundError
FloatingPointError FutureWarning GeneratorExit IOError ImportError ImportWarning
IncompleteInputError IndentationError IndexError InterruptedError IsADirectoryError KeyError
KeyboardInterrupt LookupError MemoryError ModuleNotFoundError NameError None
NotADirectoryError NotImplemented NotImplementedError OSError OverflowError
PendingDeprecationWarning PermissionError ProcessLookupError PythonFinalizationError
RecursionError ReferenceError ResourceWarning RuntimeError RuntimeWarning StopAsyncIteration
StopIteration SyntaxError SyntaxWarning SystemError SystemExit TabError TimeoutError True
TypeError UnboundLocalError UnicodeDecodeError UnicodeEncodeError UnicodeError
UnicodeTranslateError UnicodeWarning UserWarning ValueError Warning ZeroDivisionError
__build_class__ __debug__ __doc__ __import__ __loader__ __name__ __package__ __spec__ abs aiter
all anext any ascii bin bool breakpoint bytearray bytes callable chr classmethod compile complex
copyright credits delattr dict dir divmod enumerate eval exec exit filter float format frozenset
getattr globals hasattr hash help hex id input int isinstance issubclass iter len license list
locals map max memoryview min next object oct open ord pow print property quit range repr
reversed round set setattr slice sorted staticmethod str sum super tuple type vars zip
math collections Mapping max2code_runtime
""".split())

# The module's public names (module.j2); its private ones begin `m2c_`.
PY_GENERATED = frozenset("NAME PARAMS DEGREE STRATEGY VARIANTS coefficients first_root variant "
                         "params".split())


@dataclass(frozen=True)
class Python(Language):
    name: str = "python"
    title: str = "Python"
    extension: str = ".py"
    keywords: frozenset[str] = PY_KEYWORDS
    predeclared: frozenset[str] = PY_PREDECLARED
    reserved_pattern: str = r"(?i:m2c)_|coefficients_v[0-9]+$"
    # Parameters are locals of the module's functions; a mapping names them as the .mxm does.
    shows_names: bool = False
    terminator: str = ""
    and_op: str = " and "
    functions: tuple[tuple[str, str], ...] = (
        ("sin", "math.sin"), ("cos", "math.cos"), ("tan", "math.tan"), ("sqrt", "math.sqrt"),
        ("exp", "math.exp"), ("log", "math.log"), ("abs", "abs"), ("atan", "math.atan"),
        ("atan2", "math.atan2"), ("asin", "math.asin"), ("acos", "math.acos"),
        ("sinh", "math.sinh"), ("cosh", "math.cosh"), ("tanh", "math.tanh"),
    )

    def block_text(self, text: str) -> str:
        """Flush left, as Python's top level must be: a block written on its brace's line
        (`initialise python { c = [0.0] }`) or indented inside its braces was an
        IndentationError.  The first line, when it shares the brace's line, loses its spaces;
        the others their common indentation."""
        lines = text.split("\n")
        if lines and lines[0].strip():
            rest = textwrap.dedent("\n".join(lines[1:])).split("\n") if len(lines) > 1 else []
            lines = [lines[0].strip(), *rest]
        else:
            lines = textwrap.dedent("\n".join(lines)).split("\n")
        while lines and not lines[0].strip():
            lines.pop(0)
        while lines and not lines[-1].strip():
            lines.pop()
        return "\n".join(line.rstrip() for line in lines)

    def join_lines(self, lines: list[str], indent: int) -> str:
        return "(" + super().join_lines(lines, indent) + ")" if len(lines) > 1 else lines[0]

    def power_call(self, base: str, exponent: str) -> str:
        return f"({base})**({exponent})"

    def generated(self, module: str) -> frozenset[str]:
        return PY_GENERATED

    def module_name_problem(self, module: str) -> str | None:
        if module in self.keywords:
            return "a Python keyword (the module could not be imported)"
        if module in ("math", "max2code_runtime"):
            return "the name of a module the generated module imports"
        return None

    # CPython's compiler fails on a chain of about 3000 additions (RecursionError during
    # compilation: `a + b + ...` nests one level per term), so a longer sum is written as
    # math.fsum of a tuple, which is flat (and exactly rounded).
    long_sum: int = 1000

    def _print(self, e: Expr) -> tuple[str, int]:
        if isinstance(e, Add) and len(e.args) > self.long_sum:
            return f"math.fsum(({', '.join(self.expr(a) for a in e.args)}))", P_ATOM
        return super()._print(e)

    def line_directive(self, pos: Pos) -> str:
        return f"# {self.comment_text(pos.file)}:{pos.line}"

    def comment_text(self, text: str) -> str:
        """Safe in a `#` comment and inside the module's docstring: backslashes and quotes are
        escaped too (a path with `\\N` or `\"\"\"` would otherwise end or break the string)."""
        return super().comment_text(text.replace("\\", "\\\\").replace('"', '\\"'))
