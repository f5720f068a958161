"""Python: a module on the max2code_runtime package (cffi, or pure Python)."""

from ..entry import Entry
from .printer import Python
from .runtime import info

ENTRY = Entry(Python(), __name__, harness="PythonHarness", runtime=info)
