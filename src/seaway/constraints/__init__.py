"""Operational constraints: keep-away buffers from land or severe ice and polygon zones
(exclusion or penalty) rasterised on a chart, and their time-route forms (hard buffers, zones
with time windows). Via points and turn penalties act in the search (seaway.engine)."""

from ..base.units import EARTH_RADIUS_KM
from ..chart.distance import distance_to
from .timed import hard_only, timed_zone_engine
from .zones import KeepAway, Zone, constrain, constraint_factor, rasterise_zone

__all__ = [
    "KeepAway",
    "Zone",
    "constrain",
    "constraint_factor",
    "rasterise_zone",
    "distance_to",
    "hard_only",
    "timed_zone_engine",
    "EARTH_RADIUS_KM",
]
