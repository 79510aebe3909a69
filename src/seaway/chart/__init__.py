"""The chart layer: the validated raster the engine reads (Chart, as_chart), CF coordinate and
variable roles, points on a chart (locate, describe, nearest passable pixel), leg pricing of
arbitrary straight legs, and distance to a mask."""

from .locate import describe, locate, nearest_passable
from .raster import Chart, as_chart

__all__ = ["Chart", "as_chart", "locate", "describe", "nearest_passable"]
