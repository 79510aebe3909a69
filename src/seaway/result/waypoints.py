"""The one list of a route's waypoints that every output gives: the GeoJSON line, the GPX and RTZ
waypoints, the CSV rows, the HTML map's line and markers, and the leg table all read their
points (and, on a clock with a departure, their ETAs and ETDs) from waypoint_list(route), so that
one route exports the same vertices, as many, at the same positions and times in every format.

The waypoints are the route's ends and every course change (Route.waypoint_index; on a corridor
route every node); each leg between them is the great circle the route was costed along."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..base import sphere as geo
from .schedule import dated_schedule


def wrap180(v) -> float:
    """A longitude in [-180, 180) as the files write it, except that +180 (or 540, ...) stays +180
    rather than becoming -180."""
    w = float(geo.wrap_lon(v))
    return 180.0 if w == -180.0 and v > 0 else w


@dataclass(frozen=True)
class Waypoints:
    """A route's waypoints: `index` of each in the route's vertices (route.coords), `coords` their
    (m, 2) lat/lon (geographic routes, longitudes as the chart gives them) or y/x (planar);
    `eta` and `etd` their times (datetime64) on a route with a departure, else None each."""

    index: np.ndarray
    coords: np.ndarray
    geographic: bool
    eta: tuple
    etd: tuple

    def __len__(self) -> int:
        return len(self.index)

    @property
    def lat(self) -> np.ndarray:
        return self.coords[:, 0]

    @property
    def lon(self) -> list:
        """Longitudes in [-180, 180) (+180 kept), as GPX, RTZ and CSV write them."""
        return [wrap180(x) for x in self.coords[:, 1]]

    @property
    def continuous_lon(self) -> np.ndarray:
        """Longitudes made continuous along the route (across the antimeridian they run past 180)."""
        return geo.unwrap_lon(self.coords[:, 1])

    @property
    def dated(self) -> bool:
        return len(self.eta) > 0 and self.eta[0] is not None

    def positions(self) -> list:
        """GeoJSON positions: [lon, lat] with continuous longitudes, or [x, y] on planar charts."""
        if self.geographic:
            return np.column_stack([self.continuous_lon, self.lat]).tolist()
        return self.coords[:, ::-1].tolist()


def waypoint_list(route) -> Waypoints:
    """The route's Waypoints (see the module): the ends and course changes, their positions and,
    with a departure, their ETAs and ETDs (seaway.result.schedule)."""
    index = np.asarray(route.waypoint_index, dtype=np.int64)
    coords = np.asarray(route.coords, float)[index]
    timed = dated_schedule(route)
    eta: tuple[np.datetime64 | None, ...]
    etd: tuple[np.datetime64 | None, ...]
    if timed is None:
        eta = etd = (None,) * len(index)
    else:
        eta = tuple(timed.eta(int(i)) for i in index)
        etd = tuple(timed.etd(int(i)) for i in index)
    return Waypoints(index, coords, bool(route.geographic), eta, etd)
