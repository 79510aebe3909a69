"""The route a search returns (Route, Leg): its pixels, coordinates, cost and length, and what a
navigator reads from it: waypoints, legs, the environment along them and the leg table; its
typed stats (RouteStats)."""

from .route import Leg, Route
from .stats import RouteStats, SearchStats

__all__ = ["Leg", "Route", "RouteStats", "SearchStats"]
