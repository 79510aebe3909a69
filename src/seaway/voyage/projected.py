"""Charts on projected grids: NSIDC's polar stereographic (EPSG:3411), an
ocean model's grid (ROMS, NEMO on a CF grid mapping), ...

The route is searched on the chart's own grid, in kilometres of the projection; the ends are
given in lat/lon and projected onto it, and the route's vertices come back as lat/lon for the
printed legs and every output (GeoJSON, GPX, RTZ, CSV). The projection comes from the cost
variable's CF `grid_mapping` (its crs_wkt, spatial_ref or proj4 string, else its CF parameters;
pyproj, the [ice] extra). A projected chart without one is routed in ROW,COL pixels, said so.

A projection is true to scale only somewhere (EPSG:3411 at its standard parallel, 70 N): a
projection km is 1/k true km, k the point scale factor. The search prices each pixel's step by
its true length (the cost per projection km times 1/k at the pixel, true_cost), and the route's
lengths and hours are WGS84 geodesics between its lat/lon vertices (Route.geodesic), so every
figure a navigator reads is in true km."""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..base.sphere import distance_km
from ..base.units import km_per
from ..chart.cf import coord_role, grid_mapping_crs
from ..errors import ChartError, SeawayError


@dataclass
class Projection:
    crs: object  # pyproj.CRS
    source: str  # where it was found, for the messages
    #: The point scale factor k at each pixel of the chart's grid (y, x), once scale() set it.
    k: object = None  # xarray.DataArray

    def scale(self, da_km):
        """The point scale factor k at each pixel centre of `da_km` (a DataArray with y/x in km),
        as a DataArray on (y, x): pyproj's meridional scale. On a conformal projection (polar
        stereographic, Lambert conformal, Mercator) it is the scale in every direction; on a
        non-conformal one it is assumed for every direction (the scale along the meridians; the
        error is the projection's angular distortion, which a conformal one has none of)."""
        import pyproj
        import xarray as xr

        y, x = np.meshgrid(
            np.asarray(da_km.y.values, float), np.asarray(da_km.x.values, float), indexing="ij"
        )
        lat, lon = self.to_latlon(y.ravel(), x.ravel()).T
        with np.errstate(all="ignore"):
            k = np.asarray(pyproj.Proj(self.crs).get_factors(lon, lat).meridional_scale, float)
        k = np.where(np.isfinite(k) & (k > 0), k, 1.0).reshape(y.shape)
        self.k = xr.DataArray(k, dims=("y", "x"), coords={"y": da_km.y.values, "x": da_km.x.values})
        return self.k

    def true_cost(self, cost):
        """`cost` (per projection km, on the chart's y/x grid) per true km: times 1/k at each
        pixel, so a search on it minimises the true cost (or hours) exactly."""
        if self.k is None or set(getattr(cost, "dims", ())) != {"y", "x"}:
            return cost
        k = np.asarray(self.k.transpose(*cost.dims).values, float)
        return cost.copy(data=np.asarray(cost.values, float) / k)

    def scale_note(self, water=None) -> str:
        """The correction in words, with the range of k over the chart (its water when given)."""
        k = np.asarray(self.k.values, float)
        if water is not None and np.asarray(water).any():
            k = k[np.asarray(water, bool)]
        return (
            f"distances and times in true km: the projection's scale factor k, from {k.min():.2f} "
            f"to {k.max():.2f} on this chart, is corrected (the search prices each pixel's step by "
            "its projection km / k; lengths and hours are WGS84 geodesics between the vertices)"
        )

    def to_xy_km(self, lat, lon):
        import pyproj

        t = pyproj.Transformer.from_crs("EPSG:4326", self.crs, always_xy=True)
        x, y = t.transform(lon, lat)
        return np.asarray(y) / 1000.0, np.asarray(x) / 1000.0

    def to_latlon(self, y_km, x_km) -> np.ndarray:
        import pyproj

        t = pyproj.Transformer.from_crs(self.crs, "EPSG:4326", always_xy=True)
        lon, lat = t.transform(np.asarray(x_km) * 1000.0, np.asarray(y_km) * 1000.0)
        return np.column_stack([lat, lon])


def true_cost(proj: Projection | None, cost):
    """`cost` per true km on a projected chart with its scale set (Projection.true_cost), else
    `cost` itself."""
    return cost if proj is None else proj.true_cost(cost)


def true_latlon(r, proj: Projection | None):
    """Route `r` on a projected chart with its vertices in lat/lon and its lengths in true km
    (WGS84 geodesics between them); `r` itself on a lat/lon chart."""
    if proj is None:
        return r
    return replace(r, latlon=proj.to_latlon(r.coords[:, 0], r.coords[:, 1]), geodesic=True)


def _axes(da):
    """The (y, x) 1-D coordinates of a 2-D DataArray, by CF role, or None."""
    found = {}
    for dim in da.dims:
        for c in da.coords.values():
            if c.dims == (dim,) and coord_role(str(c.name), c.attrs) in ("y", "x"):
                found[coord_role(str(c.name), c.attrs)] = c
    return (found["y"], found["x"]) if len(found) == 2 else None


def find_projection(ds, da) -> Projection | None:
    """The CRS of a projected cost DataArray from its grid mapping; None when it names none."""
    name = da.attrs.get("grid_mapping")
    if not name or _axes(da) is None:
        return None
    try:
        return Projection(*grid_mapping_crs(ds, name, str(da.name)))
    except ImportError as exc:
        raise ChartError(str(exc)) from None


def in_km(da):
    """The DataArray with its y/x coordinates in km (metres divided by 1000), as dimension
    coordinates named y and x."""
    y, x = _axes(da)
    out = []
    for c in (y, x):
        scale = km_per(c.attrs.get("units"))
        if scale is None:
            raise ChartError(
                f"{da.name}: the projected coordinate {c.name} has units {c.attrs.get('units')!r}; give metres or km"
            )
        out.append(np.asarray(c.values, float) * scale)
    da = da.drop_vars([n for n in da.coords if n not in da.dims or n in (y.name, x.name)], errors="ignore")
    da = da.rename({y.dims[0]: "y", x.dims[0]: "x"}) if (y.dims[0], x.dims[0]) != ("y", "x") else da
    return da.assign_coords(
        y=("y", out[0], {"standard_name": "projection_y_coordinate", "units": "km"}),
        x=("x", out[1], {"standard_name": "projection_x_coordinate", "units": "km"}),
    )


def end_pixel(da_km, proj: Projection, p, name: str) -> tuple[int, int]:
    """(row, col) of the pixel holding the point p = (lat, lon) on a chart in km."""
    y, x = proj.to_xy_km(p[0], p[1])
    ys, xs = np.asarray(da_km.y.values), np.asarray(da_km.x.values)
    r = (float(y) - ys[0]) / (ys[1] - ys[0]) if ys.size > 1 else 0.0
    c = (float(x) - xs[0]) / (xs[1] - xs[0]) if xs.size > 1 else 0.0
    rows, cols = ys.size, xs.size
    if not (-0.5 <= r <= rows - 0.5 and -0.5 <= c <= cols - 0.5):
        corners = proj.to_latlon([ys[0], ys[0], ys[-1], ys[-1]], [xs[0], xs[-1], xs[0], xs[-1]])
        box = ", ".join(f"{a:.2f},{b:.2f}" for a, b in corners)
        raise SeawayError(
            f"{name} {p[0]:g},{p[1]:g} lies outside the chart (its corners are at "
            f"{box} lat,lon); give a point on the chart"
        )
    return min(int(round(r)), rows - 1), min(int(round(c)), cols - 1)


def pixel_latlon(da_km, proj: Projection | None):
    """For a projected chart: a function (row, col) pixel -> (lat, lon) of its centre, as ends
    are shown to the user; None for a lat/lon chart."""
    if proj is None:
        return None
    ys, xs = np.asarray(da_km.y.values), np.asarray(da_km.x.values)

    def to_user(p):
        lat, lon = proj.to_latlon([ys[int(p[0])]], [xs[int(p[1])]])[0]
        return float(lat), float(lon)

    return to_user


def project_chart(out, ds, source) -> None:
    """A chart (seaway.voyage.chart.OpenChart `out`) on a projected grid with a known CRS: its
    rasters get coordinates in km (the ice's cost gets them when it is priced), the projection
    is kept, and the notes say so. Nothing changes when `source` (the file's cost variable)
    names no grid mapping; ValueError when its grid mapping or coordinates cannot be used."""
    proj = find_projection(ds, source)
    if proj is None:
        return
    try:
        out.grid = in_km(source)
        out.fixed_cost = None if out.fixed_cost is None else in_km(out.fixed_cost)
        out.land = None if out.land is None else in_km(out.land.astype(bool))
        out.environment = {k: in_km(v) for k, v in out.environment.items()}
    except (ValueError, KeyError, TypeError) as exc:
        raise ChartError(f"{source.name}: {exc}") from None
    out.projection = proj
    _check_latlon(out, source, proj)
    proj.scale(out.grid)
    water = None if out.land is None else ~np.asarray(out.land.transpose("y", "x").values, bool)
    out.notes.append(
        f"projected chart ({proj.crs.name}, from {proj.source}): routed on its own "
        "grid in km; --from/--to and the outputs in lat/lon"
    )
    out.notes.append(proj.scale_note(water))


def _check_latlon(out, source, proj) -> None:
    """A projected chart that also gives 2-D latitude/longitude: say how far they are from the
    projection's (the route and outputs use the projection)."""
    note = latlon_note(source, out.grid.y.values, out.grid.x.values, proj)
    if note:
        out.notes.append(f"{source.name}: {note}")


def latlon_note(source, y_km, x_km, proj) -> str | None:
    """When `source` (a DataArray on a projected grid) also gives 2-D latitude/longitude and
    they lie more than a tenth of a pixel from where the projection puts the pixel centres
    (y_km, x_km axes): the sentence saying how far, in km and pixels (else None)."""
    two = {coord_role(str(c.name), c.attrs): c for c in source.coords.values() if c.ndim == 2}
    if "lat" not in two or "lon" not in two:
        return None
    y, x = np.meshgrid(np.asarray(y_km, float), np.asarray(x_km, float), indexing="ij")
    ll = proj.to_latlon(y.ravel(), x.ravel())
    lat, lon = (np.asarray(two[k].transpose(*source.dims[-2:]).values, float).ravel() for k in ("lat", "lon"))
    if lat.size != ll.shape[0]:
        return None
    km = float(np.nanmax(distance_km(lat, lon, ll[:, 0], ll[:, 1])))
    pixel = float(min(np.min(np.abs(np.diff(y_km))), np.min(np.abs(np.diff(x_km))))) if y.size > 1 else km
    if not km > 0.1 * pixel:
        return None
    return (
        f"the file's latitude/longitude lie up to {km:.1f} km ({km / pixel:.2f} pixel) "
        "from where its grid mapping puts the pixel centres; the ends, the route and the outputs "
        "use the grid mapping"
    )


__all__ = [
    "true_cost",
    "true_latlon",
    "Projection",
    "find_projection",
    "in_km",
    "end_pixel",
    "project_chart",
    "pixel_latlon",
]
