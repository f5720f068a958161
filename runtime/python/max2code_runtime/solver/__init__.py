"""The C runtime's interval solver in pure Python, operation for operation.

``runtime/c/max2code_roots.c`` holds the algorithm and the reasons for each step (its header
documents the contract and tolerances); this is a line-by-line port, used when the C runtime
cannot be loaded through cffi.  Every floating-point operation is the C one in the same order,
so the answers are bit-identical to C's (the tests compare them on every hard case, random
polynomial and fuzz vector).  Where Python differs from C it is emulated:

* ``fma`` is correctly rounded: ``math.fma`` (Python 3.13+), else exact rational arithmetic
  rounded once (``Fraction`` to ``float`` rounds correctly), so it is slow but exact;
* division by zero gives C's +-inf/NaN instead of raising (``div``), and ``ldexp`` gives
  +-inf on overflow instead of raising (``ldexp``).

The port is split by part as the C runtime is (``runtime/c/roots/*.inc``): ``shared`` (the
constants and C's floating-point semantics), ``prepare``, ``evaluate``, ``quadratic``,
``newton``, ``bernstein``, ``isolate``, ``derivative``, ``interval``, ``spread``, ``early`` and
``never_late``.  A name one part uses from another has no leading underscore (the package is
the runtime's own); this module offers every part's names, as ``solver.py`` did.  A part calls
another's function through its own import of it: a test that replaces one replaces it in
every part (tests/runtime/spy.py).
"""

from __future__ import annotations

from .shared import *  # noqa: F401,F403
from .prepare import *  # noqa: F401,F403
from .evaluate import *  # noqa: F401,F403
from .quadratic import *  # noqa: F401,F403
from .newton import *  # noqa: F401,F403
from .bernstein import *  # noqa: F401,F403
from .isolate import *  # noqa: F401,F403
from .derivative import *  # noqa: F401,F403
from .interval import *  # noqa: F401,F403
from .spread import *  # noqa: F401,F403
from .early import *  # noqa: F401,F403
from .never_late import *  # noqa: F401,F403
