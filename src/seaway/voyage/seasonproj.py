"""A season on a projected grid (an ocean model's, e.g. ROMS's polar stereographic; NSIDC's
native grid) with a CF grid mapping, served as seaway.voyage.projected serves a static chart:
the projection is read from the grid mapping of the season's variables (find_projection, i.e.
seaway.chart.cf.grid_mapping_crs, the one CRS reader), the ends are given in lat/lon and turned
into the pixels of the grid (its own km), and the route's vertices and waits come back in
lat/lon for the leg table and every output (CSV, GeoJSON, GPX, RTZ). As on a projected chart,
the season's hours per km are per true km (times 1/k, the projection's point scale factor, at
each pixel: SeasonGrid.per_true_km) and the route's lengths are WGS84 geodesics between its
vertices. A season on a projected grid without a grid mapping is routed in (row, col) pixels,
as before."""

from __future__ import annotations

import dataclasses
from typing import TYPE_CHECKING

import numpy as np
import xarray as xr

from .projected import Projection, end_pixel, find_projection, latlon_note, pixel_latlon

if TYPE_CHECKING:
    from ..ice.seasongrid import SeasonGrid
    from ..result.route import Route

#: The season's own variables first: their grid mapping is the grid's.
_FIRST = ("CT", "SA", "thickness")


def season_projection(ds: xr.Dataset, template: xr.DataArray) -> Projection | None:
    """The projection of a season Dataset on a projected grid: the grid mapping of its first
    variable on the grid (`template`'s dimensions) that names one; None when none does (a lat/lon
    season, or a projected one without a grid mapping)."""
    dims = tuple(template.dims)
    names = [n for n in _FIRST if n in ds.data_vars] + [n for n in ds.data_vars if n not in _FIRST]
    for name in names:
        da = ds[name]
        if da.attrs.get("grid_mapping") and tuple(da.dims[-2:]) == dims:
            return find_projection(ds, da)
    return None


@dataclasses.dataclass(eq=False)
class SeasonPlane:
    """A season's projected grid: its projection and its axes in km (`axes`: a Dataset with
    coordinates y and x, the pixel centres), what OpenSeason needs to take ends in lat/lon and
    give its routes in lat/lon."""

    projection: Projection
    axes: xr.Dataset
    #: How far the file's own 2-D latitude/longitude lie from the grid mapping's, when they do.
    latlon: str | None = None

    @classmethod
    def of(cls, grid: SeasonGrid) -> SeasonPlane | None:
        """The plane of a season (seaway.ice.SeasonGrid), or None when it names no projection.
        The grid's template has its y/x coordinates in km already (SeasonGrid: planar_in_km)."""
        template = grid.template
        if len(template.dims) != 2 or any(d not in template.coords for d in template.dims):
            return None
        proj = season_projection(grid.ds, template)
        if proj is None:
            return None
        y, x = (np.asarray(template[d].values, float) for d in template.dims)
        plane = cls(proj, xr.Dataset(coords={"y": ("y", y), "x": ("x", x)}))
        plane.latlon = latlon_note(grid.ds["CT"].isel(time=0), y, x, proj)
        grid.per_true_km = 1.0 / np.asarray(proj.scale(plane.axes).values, float)
        return plane

    @property
    def note(self) -> str:
        """What routing on the plane means, in words (the season's notes, every route's)."""
        p = self.projection
        return (
            f"projected season ({p.crs.name}, from {p.source}): routed on its own grid in km; "
            "the ends (lat, lon) and the outputs in lat/lon; " + p.scale_note()
        )

    def pixel(self, point, name: str = "point") -> tuple[int, int]:
        """(row, col) of the pixel holding `point` (lat, lon); SeawayError when it lies outside
        the grid (naming the grid's corners in lat/lon)."""
        return end_pixel(self.axes, self.projection, point, name)

    def to_user(self, rc) -> tuple[float, float]:
        """(lat, lon) of the centre of pixel rc, as moved ends are shown to the user."""
        show = pixel_latlon(self.axes, self.projection)
        assert show is not None
        return show(rc)

    def in_degrees(self, r: Route) -> Route:
        """The route with its vertices (Route.latlon) and its waits in lat/lon and its lengths
        WGS84 geodesics (true km): every output, the leg table and the waits read degrees; its
        search, hours (per true km already) and pixels are unchanged."""
        yx = np.asarray(r.coords, float)  # km of the projection on the planar chart
        latlon = self.projection.to_latlon(yx[:, 0], yx[:, 1])
        voyage = r.stats.voyage
        if voyage is not None and voyage.waits:
            at = self.projection.to_latlon(
                [w.position[0] for w in voyage.waits], [w.position[1] for w in voyage.waits]
            )
            waits = tuple(w._replace(position=(float(a), float(b))) for w, (a, b) in zip(voyage.waits, at))
            stats = dataclasses.replace(r.stats, voyage=dataclasses.replace(voyage, waits=waits))
            r = dataclasses.replace(r, stats=stats)
        return dataclasses.replace(r, latlon=latlon, geodesic=True)


__all__ = ["SeasonPlane", "season_projection"]
