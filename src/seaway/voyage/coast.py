"""A finer coastline merged with a chart's own land (open_chart(land=...), ``--land FILE``): the
package's coastline (global-land-mask: GLOBE, 30 arc-seconds, about 0.93 km) by default where it
is finer than the chart's pixels, or a land mask on any lat/lon grid (NetCDF, GeoTIFF: 1 = land,
e.g. GSHHG's) or coast polygons (shapefile, GeoPackage, GeoJSON: the land's polygons).

A pixel of the route grid is land when **any** of the finer land lies in it (the land mask
sampled across the pixel at about its own resolution, or the polygons rasterised touching every
pixel they reach), so a route whose steps cross only water pixels never crosses the finer land.
The price is said: a strait narrower than about two pixels closes; a finer grid (--grid) opens it."""

from __future__ import annotations

import os

import numpy as np

from ..base.files import open_netcdf, read_geotiff
from ..errors import ChartError

#: The package's coastline and its resolution (km of latitude).
PACKAGE_COAST = "the package's coastline (global-land-mask: GLOBE, 30 arc-seconds)"
GLOBE_KM = 0.926
#: The package's coastline is merged by default on pixels up to this size (km): on coarser ones
#: any land in a pixel would close straits up to twice as wide (said; --land or --grid then).
MERGE_MAX_KM = 10.0
#: At most this many samples a side per pixel (a coarser pixel is sampled more sparsely; said).
MAX_SIDE = 12
VECTOR = (".shp", ".gpkg", ".geojson", ".json", ".zip")


def pixel_km(chart) -> float:
    """The larger side of the chart's pixels in km (lat/lon: at its mean latitude)."""
    g = chart.grid
    if chart.projection is not None:
        return float(max(abs(np.diff(g.y.values[:2]))[0], abs(np.diff(g.x.values[:2]))[0]))
    lat, lon = _axes(g)
    dlat = abs(float(lat[1] - lat[0])) if lat.size > 1 else 0.0
    dlon = abs(float(lon[1] - lon[0])) if lon.size > 1 else 0.0
    return 111.2 * max(dlat, dlon * np.cos(np.radians(float(np.mean(lat)))))


def _axes(g):
    names = {str(d).lower(): d for d in g.dims}
    lat = next(g[names[n]].values for n in ("lat", "latitude") if n in names)
    lon = next(g[names[n]].values for n in ("lon", "longitude") if n in names)
    return np.asarray(lat, float), np.asarray(lon, float)


def geographic(chart) -> bool:
    dims = {str(d).lower() for d in chart.grid.dims}
    return chart.projection is not None or ({"lat", "lon"} <= dims or {"latitude", "longitude"} <= dims)


def coast_land(chart, source=None):
    """(land mask on the chart's grid in its layout, what it is in words, its resolution in km)
    from `source`: None for the package's coastline, or a file (see the module)."""
    if source is None:
        from global_land_mask import globe

        return _any_land(chart, globe.is_land, 1.0 / 120.0, 1.0 / 120.0, GLOBE_KM), PACKAGE_COAST, GLOBE_KM
    path = os.fspath(source)
    if not os.path.exists(path):
        raise ChartError(
            f"{path}: no such land file (a land mask: NetCDF or GeoTIFF, 1 = land; or coast polygons: .shp, .gpkg)"
        )
    if path.lower().endswith(VECTOR) or os.path.isdir(path):
        return _polygons(chart, path), f"{os.path.basename(path)} (land polygons)", 0.0
    lookup, dlat, dlon = _raster(path)
    km = dlat * 111.2
    return (
        _any_land(chart, lookup, dlat, dlon, km),
        f"{os.path.basename(path)} (a land mask of {km:.2g} km)",
        km,
    )


def _raster(path):
    """(lookup (lat, lon) -> land, its cells' size in degrees of latitude and longitude) of a land
    mask on a regular lat/lon grid."""
    if path.lower().endswith((".tif", ".tiff")):
        da = read_geotiff(path, error=ChartError)
    else:
        ds = open_netcdf(path, "a land mask is NetCDF or GeoTIFF on a lat/lon grid, 1 = land", ChartError)
        name = "land" if "land" in ds else next((n for n, v in ds.data_vars.items() if v.ndim == 2), None)
        if name is None:
            raise ChartError(f"{path}: no 2-D variable to read as land (name it `land`, 1 = land)")
        da = ds[name]
    try:
        lat, lon = _axes(da)
    except StopIteration:
        raise ChartError(f"{path}: a land mask needs lat/lon axes; its dims are {da.dims}") from None
    da = da.transpose(
        *[d for d in da.dims if str(d).lower() in ("lat", "latitude")],
        *[d for d in da.dims if str(d).lower() in ("lon", "longitude")],
    )
    values = np.nan_to_num(np.asarray(da.values, float)) > 0
    dlat, dlon = float(lat[1] - lat[0]), float(lon[1] - lon[0])

    def lookup(la, lo):
        i = np.rint((la - lat[0]) / dlat).astype(np.int64)
        j = np.rint((((lo - lon[0]) % 360.0) if lon[-1] - lon[0] > 359 else (lo - lon[0])) / dlon).astype(
            np.int64
        )
        inside = (i >= 0) & (i < lat.size) & (j >= 0) & (j < lon.size)
        out = np.zeros(la.shape, bool)
        out[inside] = values[i[inside], j[inside]]
        return out

    return lookup, abs(dlat), abs(dlon)


def _any_land(chart, is_land, dlat_land, dlon_land, km):
    """Any land of `is_land` in each pixel: on a lat/lon chart a lattice at half the land's cells
    (in degrees of latitude and of longitude, the pixels' edges included) reduced pixel by pixel;
    on a projected chart samples across each pixel (_sampled)."""
    if chart.projection is not None:
        return _sampled(chart, is_land, km)
    g = chart.grid
    lat, lon = _axes(g)
    lat_first = [str(d).lower() for d in g.dims][0] in ("lat", "latitude")
    dla, dlo = abs(float(lat[1] - lat[0])), abs(float(lon[1] - lon[0]))
    lon = np.unwrap(np.asarray(lon, float), period=360.0)
    fine_lon = np.arange(lon.min() - dlo / 2, lon.max() + dlo / 2 + dlon_land / 4, dlon_land / 2)
    col_lo = np.searchsorted(fine_lon, lon - dlo / 2 - 1e-9)
    col_hi = np.searchsorted(fine_lon, lon + dlo / 2 + 1e-9, side="right")
    out = np.zeros((lat.size, lon.size), bool)
    wrapped = (fine_lon + 180.0) % 360.0 - 180.0
    for r in range(lat.size):  # one row of pixels at a time: its lattice rows x every column
        fine_lat = np.arange(lat[r] - dla / 2, lat[r] + dla / 2 + dlat_land / 4, dlat_land / 2)
        la, lo = np.meshgrid(np.clip(fine_lat, -90, 90), wrapped, indexing="ij")
        hit = is_land(la.ravel(), lo.ravel()).reshape(la.shape).any(axis=0)
        cs = np.concatenate([[0], np.cumsum(hit)])
        out[r] = cs[col_hi] - cs[col_lo] > 0
    return out if lat_first else out.T


def samples_a_side(chart, km) -> int:
    """Samples a side of a pixel: at most half the land's resolution apart (at most MAX_SIDE)."""
    return int(min(MAX_SIDE, max(2, np.ceil(2 * pixel_km(chart) / max(km, 0.05)) + 1)))


def _sampled(chart, is_land, km):
    """Any land of `is_land` (lat, lon -> bool) within each pixel: an n x n lattice of samples a
    pixel, n from the pixel's size over the land's resolution (at most MAX_SIDE)."""
    g = chart.grid
    n = samples_a_side(chart, km)
    t = np.linspace(-0.5, 0.5, n)  # the pixel's edges included: land touching it counts
    rows, cols = g.shape
    out = np.zeros((rows, cols), bool)
    if chart.projection is not None:
        ys, xs = np.asarray(g.y.values, float), np.asarray(g.x.values, float)
        dy, dx = ys[1] - ys[0], xs[1] - xs[0]
    else:
        lat, lon = _axes(g)
        lat_first = [str(d).lower() for d in g.dims][0] in ("lat", "latitude")
        ys, xs = (lat, lon) if lat_first else (lon, lat)
        dy, dx = ys[1] - ys[0], xs[1] - xs[0]
    oy, ox = (a.ravel() for a in np.meshgrid(t * dy, t * dx, indexing="ij"))
    for r in range(rows):  # row by row: n^2 x cols samples at a time
        py = ys[r] + oy[:, None]
        px = xs[None, :] + ox[:, None]
        py = np.broadcast_to(py, px.shape)
        if chart.projection is not None:
            ll = chart.projection.to_latlon(py.ravel(), px.ravel())
            la, lo = ll[:, 0], ll[:, 1]
        elif lat_first:
            la, lo = py.ravel(), px.ravel()
        else:
            la, lo = px.ravel(), py.ravel()
        lo = (lo + 180.0) % 360.0 - 180.0
        out[r] = is_land(np.clip(la, -90, 90), lo).reshape(px.shape).any(axis=0)
    return out


def _polygons(chart, path):
    """Coast polygons rasterised onto the chart's grid, every pixel they touch (rasterio)."""
    try:
        import pyogrio.raw
        import rasterio.features
        import rasterio.transform
        import shapely
    except ImportError as exc:
        raise ChartError(
            f'{path}: coast polygons need the [ice] extra ({exc}): pip install "seaway[ice]"'
        ) from None
    try:
        meta, _, wkb, _ = pyogrio.raw.read(path, columns=[])
        geoms = shapely.from_wkb(wkb)
    except Exception as exc:  # pyogrio's DataSourceError, GEOS errors
        raise ChartError(
            f"{path}: cannot read its polygons ({exc}); give a shapefile or GeoPackage of land"
        ) from None
    geoms = shapely.make_valid(geoms[~shapely.is_missing(geoms)])
    g = chart.grid
    if chart.projection is not None:
        import pyproj

        to = pyproj.Transformer.from_crs(meta.get("crs") or "EPSG:4326", chart.projection.crs, always_xy=True)
        geoms = shapely.transform(
            geoms, lambda xy: np.column_stack(to.transform(xy[:, 0], xy[:, 1])) / 1000.0
        )
        ys, xs = np.asarray(g.y.values, float), np.asarray(g.x.values, float)
    else:
        lat, lon = _axes(g)
        ys, xs = lat, lon
    dy, dx = ys[1] - ys[0], xs[1] - xs[0]
    transform = rasterio.transform.Affine(dx, 0, xs[0] - dx / 2, 0, dy, ys[0] - dy / 2)
    shape = (ys.size, xs.size)
    burnt = rasterio.features.rasterize(
        [(geom, 1) for geom in geoms if not geom.is_empty],
        out_shape=shape,
        transform=transform,
        all_touched=True,
        dtype="uint8",
    )
    out = burnt.astype(bool)
    lat_first = chart.projection is not None or [str(d).lower() for d in g.dims][0] in ("lat", "latitude")
    return out if lat_first else out.T


def merge_coast(chart, source=None) -> None:
    """Merge the finer land of `source` (see coast_land) into the chart's land (and its ice
    layers' land, which prices the ice), and say what was done in the chart's notes."""
    mask, what, km = coast_land(chart, source)
    own = np.zeros(chart.grid.shape, bool) if chart.land is None else np.asarray(chart.land.values, bool)
    added = int((mask & ~own).sum())
    chart.land = chart.grid.copy(data=own | mask).rename("land")
    if chart.layers is not None and "land" in chart.layers and chart.layers["land"].shape == mask.shape:
        chart.layers = chart.layers.assign(
            land=chart.layers["land"].copy(data=np.asarray(chart.layers["land"].values, bool) | mask)
        )
    px = pixel_km(chart)
    chart.notes.append(
        f"land: the chart's own and {what}: a pixel with any of it is land ({added} pixels more than "
        f"the chart's); straits narrower than about two pixels ({2 * px:.0f} km) close: a finer --grid opens them on a vector chart; --land chart (land=\"chart\") keeps the chart's own land"
    )
