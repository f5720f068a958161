"""Code generation: Maxima's coefficients -> expression trees -> straight-line code and
variants -> identifiers and Jinja rendering per language."""
