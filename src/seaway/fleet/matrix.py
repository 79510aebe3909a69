"""Origin-destination matrices: one field per origin, read at every destination — one search per
origin, not one per pair. Through a season of ice charts (OpenSeason.arrival_field: the earliest
arrival at every pixel, waiting allowed), across one opened ice chart (OpenChart.arrival_field:
the least-time route's hours) or on a prepared cost chart (PreparedChart.cost_field: the least
accumulated cost)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from ..chart.cf import coord_role
from ..chart.locate import pixel_of
from ..chart.raster import as_chart
from ..engine.prepared import PreparedChart
from ..engine.reach import chart_order
from ..errors import SeawayError, SeawayTypeError
from ..voyage.projected import end_pixel


def od_matrix(source: Any, ports: Mapping[str, tuple[float, float]], **options: Any):
    """The cost from each port to each other port: a pandas DataFrame, origins as rows and
    destinations as columns, 0 on the diagonal, inf where the destination cannot be reached.

    source: an opened season (seaway.open_season; options: OpenSeason.arrival_field's, e.g.
    vessel, depart): hours, leaving at `depart`, waiting allowed; an opened ice chart
    (seaway.open_chart; options: OpenChart.arrival_field's, e.g. vessel, speed_kn): hours of
    the least-time route; or a prepared chart (seaway.prepare(cost, ...); option model): the
    least accumulated cost. Each value is the cost of the engine's route between the pair (the
    route with smooth=False costs exactly that; a smoothed one may be a little less, never
    more). Each port is read at the pixel that holds it ((lat, lon); (row, col) on a planar
    chart without a projection; on a projected chart or season, in its grid's km); a port on
    land or in ice the vessel may not use is refused as route() refuses it (give a point in
    water, or snap it first with a single route)."""
    import pandas as pd

    field_at = _fields(source, options)
    names = list(ports)
    if len(names) < 2:
        raise SeawayError("give at least two ports, a mapping name -> (lat, lon)")
    hours = np.zeros((len(names), len(names)))
    cells = None
    for i, origin in enumerate(names):
        field = field_at(tuple(ports[origin]))
        if cells is None:  # where each port lies in the fields' values (every field on one grid)
            cells = [_cell(source, field, ports[n], n) for n in names]
        values = np.asarray(getattr(field, "values", field), float).ravel()
        for j, cell in enumerate(cells):
            if i != j:
                hours[i, j] = float(values[cell])
    out = pd.DataFrame(
        hours, index=pd.Index(names, name="origin"), columns=pd.Index(names, name="destination")
    )
    attrs = getattr(field, "attrs", {})
    out.attrs.update(
        units=attrs.get("units", ""), departure=attrs.get("departure"), ice_class=attrs.get("ice_class")
    )
    return out


def _fields(source, options):
    """origin -> the source's field from it, with `options`."""
    if isinstance(source, PreparedChart):
        bad = sorted(set(options) - {"model"})
        if bad:
            raise SeawayTypeError(f"od_matrix on a prepared chart takes model=, not {bad}")
        return lambda origin: source.cost_field(origin, model=options.get("model"))
    if callable(getattr(source, "arrival_field", None)):
        return lambda origin: source.arrival_field(origin, **options)
    what = "a cost raster: prepare it first (seaway.prepare(cost, land=...))"
    raise SeawayTypeError(
        "od_matrix needs an opened season (seaway.open_season), an opened ice chart "
        f"(seaway.open_chart) or a prepared chart (seaway.prepare), not {type(source).__name__}"
        + (f"; for {what}" if hasattr(source, "shape") else "")
    )


def _cell(source, field, point, name: str) -> int:
    """The flat index into `field`'s values of the pixel holding `point`, as the engine finds an
    end's pixel (refused when it lies outside the grid)."""
    label = f"port {name}"
    if isinstance(source, PreparedChart):
        return int(chart_order(_index(field), source.chart)[pixel_of(source.chart, point, label)])
    plane = getattr(source, "plane", None)
    if plane is not None:  # a projected season (seaway.voyage.seasonproj.SeasonPlane)
        return _flat(np.asarray(field.values), plane.pixel(point, label))
    projection = getattr(source, "projection", None)
    if projection is not None:  # a projected chart: its field on y/x in km
        return _flat(np.asarray(field.values), end_pixel(field, projection, point, label))
    roles = [coord_role(d, field[d].attrs) for d in field.dims]
    if hasattr(source, "plane") and roles != ["lat", "lon"]:
        raise SeawayError(
            f"od_matrix reads ports on a lat/lon season; this one is on {tuple(field.dims)}: "
            "give its grid mapping (CF grid_mapping) to read ports in lat/lon, or route the pairs "
            "with route_voyages"
        )
    chart = as_chart(_index(field))  # the engine's own reading of the grid (row order, longitudes)
    return int(chart.values[pixel_of(chart, point, label)])


def _index(field):
    """`field` holding, at every pixel, its flat index in the field's own values."""
    n = int(np.prod(np.shape(field)))
    index = np.arange(n, dtype=float).reshape(np.shape(field))
    return field.copy(data=index) if hasattr(field, "copy") and hasattr(field, "dims") else index


def _flat(values, rc) -> int:
    return int(np.ravel_multi_index(tuple(int(v) for v in rc), np.shape(values)))
