"""Modula-2 (ISO, gm2): an implementation and a definition module, on the C runtime."""

from ..entry import Entry
from .printer import Modula2
from .runtime import info

ENTRY = Entry(Modula2(), __name__, harness="M2Harness", runtime=info)
