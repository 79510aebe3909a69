"""Origin-destination matrices through a season of ice charts: one time field per origin
(OpenSeason.arrival_field: the earliest arrival at every pixel, waiting allowed), read at every
destination — one search per origin, not one per pair."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from ..chart.cf import coord_role
from ..errors import SeawayError, SeawayTypeError


def od_matrix(season: Any, ports: Mapping[str, tuple[float, float]], **options: Any):
    """Hours from each port to each other port through `season` (an OpenSeason), leaving at
    `depart` with `vessel` (options: OpenSeason.arrival_field's). A pandas DataFrame, origins
    as rows and destinations as columns: the hours of the engine's route (the route with
    smooth=False arrives exactly then; a smoothed one may be a little quicker, never later);
    0 on the diagonal; inf where the ice never lets the vessel reach the destination. Each port
    is read at the pixel that holds it; a port in ice no chart opens, or on land, is refused as
    route() refuses it (give a point in water, or snap it first with a single route)."""
    import pandas as pd

    if not callable(getattr(season, "arrival_field", None)):
        raise SeawayTypeError(
            f"od_matrix needs an opened season (seaway.open_season), not {type(season).__name__}"
        )
    names = list(ports)
    if len(names) < 2:
        raise SeawayError("give at least two ports, a mapping name -> (lat, lon)")
    hours = np.zeros((len(names), len(names)))
    for i, origin in enumerate(names):
        field = season.arrival_field(tuple(ports[origin]), **options)
        for j, dest in enumerate(names):
            if i != j:
                hours[i, j] = _at(field, ports[dest], dest)
    out = pd.DataFrame(
        hours, index=pd.Index(names, name="origin"), columns=pd.Index(names, name="destination")
    )
    out.attrs.update(
        units="h", departure=field.attrs.get("departure"), ice_class=field.attrs.get("ice_class")
    )
    return out


def _at(field, point, name: str) -> float:
    """The field's value at the pixel holding `point` (lat, lon): the pixel whose centre is
    nearest, refused when the point lies outside the grid."""
    roles = [coord_role(d, field[d].attrs) for d in field.dims]
    if roles != ["lat", "lon"]:
        raise SeawayError(
            f"od_matrix reads ports on a lat/lon season; this one is on {tuple(field.dims)}: "
            "route the pairs with route_voyages instead"
        )
    lat, lon = (field[d].values for d in field.dims)
    half = [abs(float(np.diff(c[:2])[0])) / 2 if c.size > 1 else np.inf for c in (lat, lon)]
    if not (lat.min() - half[0] <= point[0] <= lat.max() + half[0]) or not (
        lon.min() - half[1] <= point[1] <= lon.max() + half[1]
    ):
        raise SeawayError(f"port {name} at {tuple(point)} lies outside the season's grid: give a point on it")
    i, j = int(np.abs(lat - point[0]).argmin()), int(np.abs(lon - point[1]).argmin())
    return float(field.values[i, j])
