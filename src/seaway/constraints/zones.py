"""Operational constraints applied to a chart before the search.

* `KeepAway`: a minimum distance from land or from severe ice (hard: impassable within `km`),
  and a soft penalty that decays linearly with distance out to `soft_km`.
* `Zone`: an exclusion or penalty area given as a shapely geometry, a GeoJSON mapping or a
  vector file, rasterised once on the chart's pixel centres.

Both change the cost raster only (a multiplier >= 1 per pixel, inf where excluded), so every
search and every edge-cost model sees them; `constrain()` returns the new raster. Distances are
between pixel centres: great-circle km on lat/lon charts, chart units (dx, dy) on planar ones.
Via-points and the turn penalty act in the search itself (`PreparedChart.route(via=...,
turn_penalty=...)`)."""

from __future__ import annotations

import math
from collections.abc import Collection
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from ..chart.distance import distance_to
from ..chart.raster import Chart, as_chart
from ..errors import ChartError, SeawayError, SeawayTypeError

if TYPE_CHECKING:
    import xarray as xr


@dataclass(frozen=True)
class KeepAway:
    """Keep `km` away from land (ice=None) or from severe ice, and pay a penalty closer than
    `soft_km`.

    km: pixels whose centre lies within `km` of a feature pixel's centre (the feature itself
        included) become impassable; 0 keeps only the feature itself out (for ice) or adds
        nothing (for land, which is already impassable).
    soft_km: out to this distance (>= km) the cost is multiplied by
        1 + penalty * (soft_km - d) / (soft_km - km), i.e. 1 + penalty next to the hard limit,
        falling linearly to 1 at soft_km. 0: no soft penalty.
    penalty: the extra cost factor at the hard limit (>= 0).
    ice: None (keep away from land: the chart's land mask and impassable pixels), a number (a
        cost threshold: pixels whose cost is >= it count as severe ice), or a boolean mask /
        DataArray of the chart's shape, e.g. ``ds.sea_ice_concentration >= 9`` or
        ``ds.stage_of_development >= 93`` (thick first-year ice and older).
    """

    km: float = 0.0
    soft_km: float = 0.0
    penalty: float = 1.0
    ice: object = None

    def __post_init__(self):
        for name in ("km", "soft_km", "penalty"):
            v = getattr(self, name)
            if (
                isinstance(v, bool)
                or not isinstance(v, (int, float, np.floating, np.integer))
                or not math.isfinite(v)
                or v < 0
            ):
                raise SeawayError(f"KeepAway.{name} must be a finite number >= 0, got {v!r}")
        if self.soft_km and self.soft_km <= self.km:
            raise SeawayError(
                f"KeepAway.soft_km ({self.soft_km:g}) must exceed km ({self.km:g}); "
                "give soft_km=0 for a hard limit only"
            )
        if self.ice is None and self.km == 0 and self.soft_km == 0:
            raise SeawayError(
                "KeepAway from land with km=0 and soft_km=0 changes nothing; give km= "
                "(hard limit) and/or soft_km= (soft penalty)"
            )


@dataclass(frozen=True)
class Zone:
    """An exclusion (penalty=inf) or penalty area (cost x penalty, penalty >= 1).

    geometry: a shapely (Multi)Polygon, a GeoJSON mapping (geometry, Feature or
        FeatureCollection), or a path to a vector file (GeoJSON, shapefile, GeoPackage; read
        with pyogrio). Coordinates are lon/lat degrees on lat/lon charts and the chart's y/x
        units on projected charts (pass `crs` to reproject lon/lat geometries onto a projected
        chart, given `chart_crs` to constrain()).
    penalty: inf excludes the area; a finite factor >= 1 multiplies its cost.
    name: for messages and tables.
    crs: the geometry's CRS when it differs from the chart's (e.g. "EPSG:4326").
    """

    geometry: object
    penalty: float = math.inf
    name: str = "zone"
    crs: object = None
    #: (closes, opens): the exclusion holds only in this window, for time routes
    #: (seaway.weather.route_time); datetimes, or hours after departure. None: always.
    active: tuple | None = None

    def __post_init__(self):
        p = self.penalty
        if (
            isinstance(p, bool)
            or not isinstance(p, (int, float, np.floating, np.integer))
            or math.isnan(p)
            or p < 1
        ):
            raise SeawayError(f"Zone penalty must be >= 1 (a cost factor) or inf (an exclusion), got {p!r}")
        if self.active is not None:
            if not (isinstance(self.active, (tuple, list)) and len(self.active) == 2):
                raise SeawayError(f"Zone.active must be a (closes, opens) pair of times, got {self.active!r}")
            if math.isfinite(p):
                raise SeawayError("a time window applies to exclusion zones (penalty=inf) only")


# -- zones --------------------------------------------------------------------------------------
def _geometry(zone: Zone, chart_crs):
    import shapely
    from shapely.geometry import shape

    geom = zone.geometry
    if isinstance(geom, (str, bytes)) or hasattr(geom, "__fspath__"):
        from pyogrio.raw import read

        try:
            meta, _, wkb, _ = read(geom, read_geometry=True)
        except Exception as exc:  # noqa: BLE001 - the reader's many error types
            raise SeawayError(f"zone {zone.name!r}: cannot read {geom!s}: {exc}") from None
        if wkb is None or len(wkb) == 0:
            raise SeawayError(f"zone {zone.name!r}: {geom!s} holds no geometries")
        geom, src_crs = shapely.union_all(shapely.from_wkb(wkb)), meta.get("crs") or zone.crs
    elif isinstance(geom, dict):
        kind = geom.get("type")
        if kind == "FeatureCollection":
            geom = shapely.union_all([shape(f["geometry"]) for f in geom.get("features", [])])
        elif kind == "Feature":
            geom = shape(geom["geometry"])
        else:
            try:
                geom = shape(geom)
            except Exception as exc:  # noqa: BLE001
                raise SeawayError(f"zone {zone.name!r}: not a GeoJSON geometry: {exc}") from None
        src_crs = zone.crs
    elif isinstance(geom, shapely.Geometry):
        src_crs = zone.crs
    else:
        raise SeawayTypeError(
            f"zone {zone.name!r}: geometry must be a shapely geometry, a GeoJSON "
            f"mapping or a vector file path, got {type(geom).__name__}"
        )
    if geom.is_empty or geom.area == 0:
        raise SeawayError(f"zone {zone.name!r} has no area; give a Polygon or MultiPolygon")
    if not geom.is_valid:
        geom = shapely.make_valid(geom)
    if src_crs is not None and chart_crs is not None:
        from pyproj import CRS, Transformer

        if CRS.from_user_input(src_crs) != CRS.from_user_input(chart_crs):
            t = Transformer.from_crs(src_crs, chart_crs, always_xy=True)
            geom = shapely.transform(geom, lambda xy: np.column_stack(t.transform(xy[:, 0], xy[:, 1])))
    return geom


def rasterise_zone(zone: Zone, chart: Chart, chart_crs=None) -> np.ndarray:
    """Boolean (rows, cols): the pixels whose centre lies inside or on the zone's boundary.

    Lat/lon charts: the geometry is in lon/lat degrees; longitudes are taken modulo 360 into
    the geometry's own range, so -180..180 geometries fit 0..360 charts. Projected charts: the
    geometry is in the chart's y/x units (or reprojected from `zone.crs` to `chart_crs`)."""
    import shapely

    geom = _geometry(zone, chart_crs)
    shapely.prepare(geom)
    minx, miny, maxx, maxy = geom.bounds
    if chart.geographic:
        xs = (chart.lon - minx) % 360.0 + minx  # the same meridians in the geometry's range
        ys = np.asarray(chart.lat)
    else:
        xs, ys = np.asarray(chart.x), np.asarray(chart.y)
    cols = np.nonzero((xs >= minx) & (xs <= maxx))[0]
    rows = np.nonzero((ys >= miny) & (ys <= maxy))[0]
    out = np.zeros(chart.shape, dtype=bool)
    if cols.size and rows.size:
        X, Y = np.meshgrid(xs[cols], ys[rows])
        out[np.ix_(rows, cols)] = shapely.intersects_xy(geom, X, Y)
    return out


# -- the cost raster ----------------------------------------------------------------------------
def _mask_of(ice, chart: Chart, template) -> np.ndarray:
    if isinstance(ice, (int, float, np.integer, np.floating)) and not isinstance(ice, bool):
        if not np.isfinite(ice) or ice < 0:
            raise SeawayError(f"KeepAway.ice as a cost threshold must be finite and >= 0, got {ice!r}")
        with np.errstate(invalid="ignore"):
            return np.isfinite(chart.values) & (chart.values >= ice)
    if hasattr(ice, "dims") and template is not None and set(ice.dims) == set(template.dims):
        ice = ice.transpose(*template.dims)
    arr = np.asarray(ice.values if hasattr(ice, "dims") else ice)
    if arr.shape != chart.shape:
        raise ChartError(
            f"KeepAway.ice mask has shape {arr.shape} but the chart has {chart.shape}; "
            "give a boolean mask of the chart's shape or a cost threshold"
        )
    if arr.dtype != np.bool_:
        raise SeawayTypeError(
            f"KeepAway.ice mask must be boolean (e.g. ds.sea_ice_concentration >= 9), got dtype {arr.dtype}"
        )
    return arr


def constraint_factor(chart: Chart, keep_away=(), zones=(), *, chart_crs=None) -> np.ndarray:
    """The per-pixel cost multiplier (>= 1, inf where excluded) of the keep-away buffers and
    zones on a validated chart."""
    factor = np.ones(chart.shape)
    blocked = ~(np.isfinite(chart.values) & (chart.values >= 0))
    if chart.land is not None:
        blocked |= chart.land.astype(bool)
    for k in keep_away:
        if not isinstance(k, KeepAway):
            raise SeawayTypeError(f"keep_away takes KeepAway objects, got {type(k).__name__}")
        feature = blocked if k.ice is None else _mask_of(k.ice, chart, chart.template)
        d = distance_to(feature, chart, max(k.km, k.soft_km))
        if k.ice is not None or k.km > 0:
            factor[d <= k.km] = np.inf
        if k.soft_km:
            soft = (d > k.km) & (d < k.soft_km)
            factor[soft] *= 1 + k.penalty * (k.soft_km - d[soft]) / (k.soft_km - k.km)
    for z in zones:
        if not isinstance(z, Zone):
            raise SeawayTypeError(f"zones takes Zone objects, got {type(z).__name__}")
        if z.active is not None:
            raise SeawayError(
                f"zone {z.name!r} has a time window, which only a time route can "
                "follow: pass it to seaway.weather.route_time(zones=...), or drop "
                "active= for a static chart"
            )
        factor[rasterise_zone(z, chart, chart_crs)] *= z.penalty
    return factor


def constrain(
    cost: npt.ArrayLike | xr.DataArray,
    *,
    keep_away: KeepAway | Collection[KeepAway] = (),
    zones: Zone | Collection[Zone] = (),
    lat: npt.ArrayLike | None = None,
    lon: npt.ArrayLike | None = None,
    dx: float = 1.0,
    dy: float = 1.0,
    land: npt.ArrayLike | xr.DataArray | None = None,
    chart_crs: object = None,
) -> npt.NDArray[np.float64] | xr.DataArray:
    """The cost raster with keep-away buffers and zones applied: cost x factor, inf where
    excluded. A DataArray in gives a DataArray out (same coordinates); a numpy array gives a
    float64 array. Arguments as in seaway.route(); `chart_crs` reprojects zones with a `crs`
    onto a projected chart."""
    if isinstance(keep_away, KeepAway):
        keep_away = [keep_away]
    if isinstance(zones, Zone):
        zones = [zones]
    chart = as_chart(cost, lat=lat, lon=lon, dx=dx, dy=dy, land=land)
    factor = constraint_factor(chart, list(keep_away), list(zones), chart_crs=chart_crs)
    with np.errstate(invalid="ignore"):  # 0 x inf: a free pixel inside an exclusion
        values = chart.values.astype(np.float64) * factor
    values[np.isinf(factor)] = np.inf
    if chart.template is None:
        return values
    out = chart.template.copy(data=values)
    out.attrs = dict(out.attrs, constraints=f"{len(keep_away)} keep-away, {len(zones)} zone(s)")
    if hasattr(cost, "dims") and out.dims != cost.dims:
        out = out.transpose(*cost.dims)
    return out
