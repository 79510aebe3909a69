"""seaway: optimal ship routes through sea ice, waves and weather on raster charts.

The C++ core searches the implicit graph whose vertices are a chart's pixels and whose edges
join each pixel to the pixels of the k x k square around it (Dijkstra and exact A*)."""

from importlib.metadata import PackageNotFoundError, version

from . import export as export  # seaway.export.write(...) after `import seaway` (no plotting packages)
from .engine import (
    PreparedChart,
    SnapError,
    SnappedEnds,
    cost_field,
    explain_no_route,
    prepare,
    route,
    snap_ends,
)
from .errors import ChartError, ForecastError, NoRouteError, SeawayError, SeawayTypeError, VesselFileError
from .fleet import route_many
from .output import webmap as _webmap  # noqa: F401 - puts Route.explore() and .to_html() in place
from .result import Leg, Route
from .smoothing import smooth
from .voyage import ChartOptions, OpenChart, OpenForecast, OpenSeason, open_chart, open_forecast, open_season

__all__ = [
    "route",
    "cost_field",
    "prepare",
    "PreparedChart",
    "Route",
    "NoRouteError",
    "Leg",
    "smooth",
    "route_many",
    "snap_ends",
    "SnappedEnds",
    "SnapError",
    "explain_no_route",
    "open_chart",
    "open_season",
    "open_forecast",
    "OpenForecast",
    "OpenChart",
    "OpenSeason",
    "ChartOptions",
    "SeawayError",
    "SeawayTypeError",
    "ChartError",
    "ForecastError",
    "VesselFileError",
]
try:
    __version__ = version("seaway")  # one version: pyproject.toml's, from the package metadata
except PackageNotFoundError:  # run from a source tree that was never installed
    __version__ = "0+unknown"
