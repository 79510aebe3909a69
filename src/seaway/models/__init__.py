"""Cost models: what a route minimises. Each is one Python class over one C++ functor; each
declares its capabilities (static, symmetric, turn penalty, time-dependent, chainable,
smoothable) once, as class attributes of seaway.models.CostModel.

PreparedChart.route(start, end, model=...) is the one query; seaway.route, route_time,
route_fuel and route_safest build a model and call it."""

from .base import EDGE_COSTS, CostModel, EdgeCost, EnteredPixel, TurnPenalised, as_model
from .forecast import Fuel, TravelTime, WaveDanger
from .season import IceSeasonTime, IceWeatherTime

__all__ = [
    "EDGE_COSTS",
    "CostModel",
    "EdgeCost",
    "EnteredPixel",
    "Fuel",
    "IceSeasonTime",
    "IceWeatherTime",
    "TravelTime",
    "TurnPenalised",
    "WaveDanger",
    "as_model",
]
