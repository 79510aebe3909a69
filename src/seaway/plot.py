"""seaway.plot: PNG maps of routes and cost fields (the module is seaway.output.plot)."""

import sys

from .output import plot as _module

sys.modules[__name__] = _module
