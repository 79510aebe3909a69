"""Weather routing: forecasts of currents, wind and waves in (CF NetCDF, projected model grids),
the quickest route (Khokhlov's wave speed loss and currents, exact for FIFO forecasts), the route
of least wave danger by heading, the least time in danger when no safe route exists, fuel-optimal
engine settings, and re-planning during the voyage."""

from ..base.units import KNOTS_PER_MS
from ..vessel import Vessel  # noqa: F401 - the same class as seaway.vessel.Vessel, documented there
from .files import decode_time, read_forecasts
from .forecast import STANDARD_NAMES, find_fields, grib_times, read_forecast, to_latlon
from .fuel import FuelCurve, route_fuel, route_min_fuel, tradeoff
from .grid import ForecastGrid
from .projected import is_projected, on_grid
from .routes import position_at, replan, rhumb_line_km, route_ice_weather, route_safest, route_time
from .sample import kara_autumn

__all__ = [
    "ForecastGrid",
    "route_time",
    "route_ice_weather",
    "route_safest",
    "rhumb_line_km",
    "position_at",
    "replan",
    "KNOTS_PER_MS",
    "STANDARD_NAMES",
    "find_fields",
    "read_forecast",
    "grib_times",
    "to_latlon",
    "FuelCurve",
    "route_fuel",
    "route_min_fuel",
    "tradeoff",
    "decode_time",
    "on_grid",
    "is_projected",
    "read_forecasts",
    "kara_autumn",
]
