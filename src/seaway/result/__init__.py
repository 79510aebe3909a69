"""The route a search returns (Route, Leg): its pixels, coordinates, cost and length, and what a
navigator reads from it: waypoints, legs, the environment along them and the leg table; its
typed stats (RouteStats)."""

from .leg import Leg
from .route import Route
from .stats import RouteStats, SearchStats

__all__ = ["Leg", "Route", "RouteStats", "SearchStats"]
