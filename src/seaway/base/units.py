"""Units and constants, written once: every module takes them from here."""

from __future__ import annotations

import math

#: The sphere the engine measures on (km): the IUGG mean Earth radius R1.
EARTH_RADIUS_KM = 6371.0088
#: One international nautical mile in km.
KM_PER_NM = 1.852
#: Knots per metre per second (1 kn = 1852 m / 3600 s).
KNOTS_PER_MS = 3600.0 / 1852.0
#: Length of one degree of a great circle, km.
KM_PER_DEG = math.pi * EARTH_RADIUS_KM / 180.0
