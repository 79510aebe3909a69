"""seaway.export: a route as GeoJSON, GPX, CSV, RTZ or HTML (the module is seaway.output.export)."""

import sys

from .output import export as _module

sys.modules[__name__] = _module
