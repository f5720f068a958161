"""Exceptions that stop the engine's step at an event's time, raised out of its callbacks
(BaseException: a game's `except Exception` cannot swallow them)."""


class Rebuild(BaseException):
    """The world went stale in a collision callback: the step stops at that event's time and
    resumes in the rebuilt world (max2code.pge.physics)."""


class WindowEnd(BaseException):
    """A sprung body's window ends at this event's time (max2code.pge.springs)."""
