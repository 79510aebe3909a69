"""Routes from one start to many ends through a season (OpenSeason.routes): the vessel's model
is built once, each end is checked and snapped as a single route's is, and one Dijkstra search
per start pixel used runs until every end is reached (seaway.PreparedChart.routes). Each
answer is what ``OpenSeason.route(start, end, method="dijkstra", ...)`` gives, or the
SeawayError it raises, in that end's place: a batch of voyages from one port costs one search
where single routes cost one each (seaway.fleet.route_voyages)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from ..errors import NoRouteError, SeawayError
from .seasonroutes import ends_used, explain, finish, plan

if TYPE_CHECKING:
    from ..result.route import Route


def season_routes(
    season,
    start: tuple[float, float],
    ends: Sequence[tuple[float, float]],
    *,
    vessel: Any = "Arc7",
    speed_kn: float | None = None,
    depart: Any = None,
    speed_table: Any = None,
    fast_ice: str | float | None = None,
    concentration_limit: bool = True,
    snap_km: float | None = None,
    neighbourhood: int = 5,
    smooth: bool = True,
    name: str = "seaway season route",
) -> list[Route | SeawayError]:
    """See OpenSeason.routes."""
    p = plan(season, vessel, speed_kn, depart, speed_table, fast_ice, concentration_limit)
    out: list[Route | SeawayError | None] = [None] * len(ends)
    groups: dict[tuple[int, int], list[tuple[int, Any]]] = {}  # start pixel used -> (index, its end)
    for i, end in enumerate(ends):
        try:  # a start that must move may move differently for each end (the water joining them)
            (a, b), moved, asked = ends_used(season, p, start, end, snap_km, neighbourhood)
        except SeawayError as exc:
            out[i] = exc
            continue
        groups.setdefault(a, []).append((i, (b, moved, asked)))
    chart = season.prepared(neighbourhood)
    for a, members in groups.items():
        found = chart.routes(a, [b for _, (b, _, _) in members], model=p.model)
        for (i, (b, moved, asked)), r in zip(members, found):
            if isinstance(r, NoRouteError):
                out[i] = explain(season, p, a, b, neighbourhood, asked, moved)
            else:
                try:
                    out[i] = finish(season, p, r, asked, moved, smooth, name)
                except SeawayError as exc:
                    out[i] = exc
    return [r for r in out if r is not None]
