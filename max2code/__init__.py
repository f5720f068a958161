"""max2code: Maxima collision-prediction equations to C, Python, Rust and Modula-2."""

__version__ = "0.1.0"
