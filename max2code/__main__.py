"""Allows `python -m max2code`."""

import sys

from .cli import main

sys.exit(main())
