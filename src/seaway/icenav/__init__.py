"""Voyage planning through ice: routes through a season of ice charts (season: route_season,
arrival_field; seasonwhy: a season's ends and why no route gets through it), why no route gets
through one ice chart (noroute: the ice that closes the way, the weakest class that gets
through), Andreeva 2021's time-safety Pareto routes (pareto) and the ice along a route
(summary). The ice knowledge these rest on (classes, codes, impact, POLARIS, Andreeva's
formulas, the season's charts and speeds, the readers) is seaway.ice, a layer below."""

from .noroute import explain_no_route
from .pareto import pareto_routes
from .season import arrival_field, route_season

__all__ = ["route_season", "arrival_field", "explain_no_route", "pareto_routes"]
