"""The route a search returns (Route, Leg): its pixels, coordinates, cost and length, and what a
navigator reads from it: waypoints, legs, the environment along them and the leg table."""

from .route import Leg, Route

__all__ = ["Leg", "Route"]
