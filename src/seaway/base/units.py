"""Units and constants, written once: every module takes them from here."""

from __future__ import annotations

import math
from typing import Any

#: The sphere the engine measures on (km): the IUGG mean Earth radius R1.
EARTH_RADIUS_KM = 6371.0088
#: One international nautical mile in km.
KM_PER_NM = 1.852
#: Knots per metre per second (1 kn = 1852 m / 3600 s).
KNOTS_PER_MS = 3600.0 / 1852.0
#: Length of one degree of a great circle, km.
KM_PER_DEG = math.pi * EARTH_RADIUS_KM / 180.0


def metres_per(units: object) -> float | None:
    """Metres in one of `units`, a CF / UDUNITS length unit as files write it ("m", "metres",
    "km", "kilometers", "ft", "fathoms", "100 m"), read by pint (one unit table for the whole
    package); None when it is not a length (or empty)."""
    text = str(units or "").strip()
    if not text:
        return None
    try:
        q = (
            _registry().Quantity(text)
            if any(c.isdigit() for c in text)
            else 1 * _registry().parse_units(text)
        )
        return float(q.to("m").magnitude)
    except Exception:  # pint's UndefinedUnitError, DimensionalityError, its parser's errors
        return None


def km_per(units: object) -> float | None:
    """Kilometres in one of `units` (see metres_per), or None when it is not a length."""
    m = metres_per(units)
    return None if m is None else m / 1000.0


def _registry() -> Any:
    global _UREG
    if _UREG is None:
        import pint

        _UREG = pint.UnitRegistry()
    return _UREG


_UREG: Any = None
