"""Origin-destination matrices through a season of ice charts: one time field per origin
(OpenSeason.arrival_field: the earliest arrival at every pixel, waiting allowed), read at every
destination — one search per origin, not one per pair."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from ..chart.cf import coord_role
from ..chart.locate import pixel_of
from ..chart.raster import as_chart
from ..errors import SeawayError, SeawayTypeError


def od_matrix(season: Any, ports: Mapping[str, tuple[float, float]], **options: Any):
    """Hours from each port to each other port through `season` (an OpenSeason), leaving at
    `depart` with `vessel` (options: OpenSeason.arrival_field's). A pandas DataFrame, origins
    as rows and destinations as columns: the hours of the engine's route (the route with
    smooth=False arrives exactly then; a smoothed one may be a little quicker, never later);
    0 on the diagonal; inf where the ice never lets the vessel reach the destination. Each port
    is read at the pixel that holds it (on a projected season, in its grid's km); a port in ice no chart opens, or on land, is refused as
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
                hours[i, j] = _at(field, ports[dest], dest, getattr(season, "plane", None))
    out = pd.DataFrame(
        hours, index=pd.Index(names, name="origin"), columns=pd.Index(names, name="destination")
    )
    out.attrs.update(
        units="h", departure=field.attrs.get("departure"), ice_class=field.attrs.get("ice_class")
    )
    return out


def _at(field, point, name: str, plane=None) -> float:
    """The field's value at the pixel holding `point` (lat, lon), as the engine finds an end's
    pixel (seaway.chart.locate.pixel_of: refused when it lies outside the grid). plane: a
    projected season's (seaway.voyage.seasonproj.SeasonPlane), which finds it in the grid's km."""
    if plane is not None:
        i, j = plane.pixel(point, f"port {name}")
        return float(field.values[i, j])
    roles = [coord_role(d, field[d].attrs) for d in field.dims]
    if roles != ["lat", "lon"]:
        raise SeawayError(
            f"od_matrix reads ports on a lat/lon season; this one is on {tuple(field.dims)}: "
            "give its grid mapping (CF grid_mapping) to read ports in lat/lon, or route the pairs "
            "with route_voyages"
        )
    chart = as_chart(field)  # the engine's own reading of the grid (row order, longitudes)
    return float(chart.values[pixel_of(chart, point, f"port {name}")])
