"""C: one header per equation, the C runtime compiled into the program."""

from ..entry import Entry
from .printer import C
from .runtime import info

ENTRY = Entry(C(), __name__, harness="CHarness", runtime=info)
