"""Water depth and draft: a bathymetry raster resampled onto a chart's grid,
pixels shallower than the draft plus an under-keel clearance made impassable, and the least
depth along a route.

Reading: seaway.depth.open_bathymetry (NetCDF or GeoTIFF; ETOPO/GEBCO elevation or
depth positive down, told by the CF attributes, or guessed and said so).

Resampling (`depth_on_grid`), per axis: where the chart's pixels are larger than the
bathymetry's cells, each pixel takes the SHALLOWEST depth of the sounding nodes inside it (a
binned minimum, `numpy.minimum.reduceat`: xarray's `coarsen().min()` generalised to pixel
sizes that are not whole multiples of the cell), so a shoal narrower than a pixel is never
averaged away; where the pixels are smaller, the depth is linearly interpolated at the pixel
centres (`DataArray.interp`). A pixel with any unknown node, or beyond the data, is NaN
(unknown), and with a draft NaN is impassable: nothing unknown becomes deep water. Depth <= 0
(land in the bathymetry) is impassable for every draft. Projected charts (y/x, e.g. EPSG:3413
grids of seaway.ice.grids): every node is projected and binned exactly (seaway.depth.projected).

Draft (`apply_draft`): a pixel is passable when depth >= draft + UKC. The default UKC is 10 %
of the draft (an allowance for squat and the bottom's uncertainty in sheltered water; give
your own, more in swell or over poorly surveyed ground). Andreeva 2021's depth factor f1 from this
depth: seaway.ice.andreeva.depth_factor.
"""

from __future__ import annotations

import numpy as np

from ..chart.cf import coord_role
from ..chart.locate import locate
from ..chart.raster import as_chart, from_dataarray
from ..errors import ChartError, SeawayError, SeawayTypeError
from ..result.environment import least_depth  # noqa: F401 - part of this API
from .bathymetry import Bathymetry, open_bathymetry  # noqa: F401 - part of this API
from .projected import projected_depth

DEFAULT_UKC_SHARE = 0.10


def _step(values, name):
    if values.size < 2:
        return None
    step = float(np.median(np.diff(values)))
    if step <= 0:
        raise ChartError(f"the chart's {name} must be strictly monotonic")
    return step


def _binned_min(values, nodes, centres, step, axis):
    """Min of `values` over the nodes inside each pixel [c - step/2, c + step/2), along `axis`;
    NaN for pixels with no node or reaching past the data by more than half a node spacing."""
    lo, hi = centres - step / 2, centres + step / 2
    start = np.searchsorted(nodes, lo, side="left")
    stop = np.searchsorted(nodes, hi, side="left")
    spacing = float(np.median(np.diff(nodes))) if nodes.size > 1 else step
    inside = (stop > start) & (lo >= nodes[0] - spacing / 2) & (hi <= nodes[-1] + spacing / 2)
    v = np.moveaxis(values, axis, 0)
    pad = np.concatenate([v, np.full((1,) + v.shape[1:], np.nan)])
    idx = np.column_stack([np.minimum(start, len(v)), np.minimum(stop, len(v))]).ravel()
    mins = np.minimum.reduceat(pad, idx, axis=0)[::2]
    out = np.where(inside.reshape((-1,) + (1,) * (v.ndim - 1)), mins, np.nan)
    return np.moveaxis(out, 0, axis)


def _lon_window(depth, west, east):
    """The bathymetry's columns covering [west, east] (continuous degrees, may pass 180),
    using the copies shifted by 360 when the raster is global."""
    import xarray as xr

    lon = depth.lon.values
    spacing = float(np.median(np.diff(lon)))
    shifts = (-360.0, 0.0, 360.0) if lon[-1] - lon[0] + spacing >= 360.0 - 1e-6 else (0.0,)
    parts = []
    for k in shifts:
        sel = np.nonzero((lon + k >= west - 2 * spacing) & (lon + k <= east + 2 * spacing))[0]
        if sel.size:
            parts.append(depth.isel(lon=sel).assign_coords(lon=lon[sel] + k))
    if not parts:
        return depth.isel(lon=slice(0, 0))
    return xr.concat(parts, dim="lon") if len(parts) > 1 else parts[0]


def depth_on_grid(bathymetry, like=None, *, lat=None, lon=None, crs=None):
    """Depth (m, positive down) on a chart's grid: `like` a DataArray with lat/lon coordinates
    (e.g. the cost), or 1-D `lat` and `lon` pixel centres. Shallowest node per pixel where the
    chart is coarser, linear interpolation where it is finer (module doc). A `like` with y/x
    coordinates (km or m, by their units attribute; km if none) is a projected grid in `crs`
    (default like.attrs['crs']; seaway.ice.grids projected grids): seaway.depth.projected."""
    import xarray as xr

    if isinstance(bathymetry, Bathymetry):
        depth, factor, source = bathymetry.raw, bathymetry.factor, bathymetry.path
    else:  # a DataArray of depth (m, positive down) on lat/lon, ascending
        depth, factor, source = bathymetry, 1.0, "given"
    if like is not None:
        _, coords, turned = from_dataarray(like)
        if "y" in coords:
            return _on_projected(depth, factor, turned, coords, crs or like.attrs.get("crs"))
        if "lat" not in coords:
            raise ChartError("depth needs the chart's lat/lon or y/x coordinates")
        lat, lon = coords["lat"], coords["lon"]
    lat, lon = np.asarray(lat, float), np.asarray(lon, float)
    if lon.size > 1 and np.any(np.abs(np.diff(lon)) > 180):
        lon = lon[0] + np.concatenate([[0.0], np.cumsum((np.diff(lon) + 180) % 360 - 180)])
    lat_order, lon_order = np.argsort(lat), np.argsort(lon)
    la, lo = lat[lat_order], lon[lon_order]
    dla, dlo = _step(la, "lat"), _step(lo, "lon")
    cell_la = float(np.median(np.diff(depth.lat.values)))
    cell_lo = float(np.median(np.diff(depth.lon.values)))
    half_lo = (dlo or cell_lo) / 2
    d = _lon_window(depth, lo[0] - half_lo, lo[-1] + half_lo)
    half_la = (dla or cell_la) / 2
    d = d.sel(lat=slice(la[0] - half_la - 2 * cell_la, la[-1] + half_la + 2 * cell_la))
    if d.sizes["lat"] < 2 or d.sizes["lon"] < 2:
        raise ChartError(
            f"the bathymetry ({source}, lat {float(depth.lat[0]):g}..{float(depth.lat[-1]):g}) does not cover "
            f"the chart (lat {la[0]:g}..{la[-1]:g}, lon {lo[0]:g}..{lo[-1]:g})"
        )
    values = np.asarray(d.values, dtype=np.float64) * factor  # reads only this window
    if not np.isfinite(values).any():
        raise ChartError(
            f"the bathymetry ({source}) has no data over the chart (lat {la[0]:g}.."
            f"{la[-1]:g}, lon {lo[0]:g}..{lo[-1]:g}): all missing"
        )
    rule = []
    for axis, (name, centres, step, cell) in enumerate(
        (("lat", la, dla, cell_la), ("lon", lo, dlo, cell_lo))
    ):
        nodes = d[name].values
        if step is not None and step > cell * (1 + 1e-9):
            values = _binned_min(values, nodes, centres, step, axis)
            rule.append(f"{name}: shallowest of the nodes in each pixel")
        else:
            try:
                import scipy  # noqa: F401  (DataArray.interp)
            except ImportError:
                raise ImportError(
                    'interpolating the bathymetry needs scipy: pip install "seaway[depth]"'
                ) from None
            da = xr.DataArray(values, dims=("a", "b"), coords={("a", "b")[axis]: nodes})
            values = da.interp({("a", "b")[axis]: centres}, method="linear").values
            rule.append(f"{name}: linear interpolation")
    values = values[np.argsort(lat_order)][:, np.argsort(lon_order)]
    dims = ("lat", "lon")
    out = xr.DataArray(values, dims=dims, coords={"lat": lat, "lon": lon}, name="depth")
    if like is not None and hasattr(like, "coords"):
        out = out.assign_coords(
            lat=like.coords[_dim(like, "lat")].values, lon=like.coords[_dim(like, "lon")].values
        )
        out = out.rename({"lat": _dim(like, "lat"), "lon": _dim(like, "lon")})
    out.attrs = {
        "long_name": "water depth (shallowest in the pixel)",
        "units": "m",
        "positive": "down",
        "resampling": "; ".join(rule),
    }
    return out


def _on_projected(depth, factor, like, coords, crs):

    if not crs:
        raise ChartError(
            "the chart has projected y/x coordinates but no CRS: pass crs= (e.g. "
            "'EPSG:3413'), or set the chart's attribute 'crs'"
        )
    ydim, xdim = like.dims
    units = like.coords[ydim].attrs.get("units", "km")
    values, rule = projected_depth(depth, factor, coords["y"], coords["x"], crs, units)
    out = like.copy(data=values)
    out.name = "depth"
    out.attrs = {
        "long_name": "water depth (shallowest in the pixel)",
        "units": "m",
        "positive": "down",
        "resampling": rule,
        "crs": str(crs),
    }
    return out


def _dim(da, role):

    for d in da.dims:
        if d in da.coords and coord_role(d, da.coords[d].attrs) == role:
            return d
    return role


def check_draft(draft, ukc=None) -> tuple[float, float]:
    """(draft, ukc) validated; ukc defaults to 10 % of the draft."""
    try:
        draft = float(draft)
    except (TypeError, ValueError):
        raise SeawayTypeError(f"draft must be a number of metres, got {draft!r}") from None
    if not (np.isfinite(draft) and 0 < draft < 100):
        raise SeawayError(f"draft must be in metres, more than 0 and less than 100, got {draft:g}")
    ukc = DEFAULT_UKC_SHARE * draft if ukc is None else ukc
    try:
        ukc = float(ukc)
    except (TypeError, ValueError):
        raise SeawayTypeError(f"ukc (under-keel clearance) must be a number of metres, got {ukc!r}") from None
    if not (np.isfinite(ukc) and 0 <= ukc < 100):
        raise SeawayError(f"ukc (under-keel clearance) must be in metres, 0 to 100, got {ukc:g}")
    return draft, ukc


def apply_draft(cost, depth, draft, ukc=None):
    """The cost with inf where the depth is less than draft + ukc, or unknown (NaN). depth: a
    DataArray on the cost's grid (depth_on_grid) or an array of its shape."""
    draft, ukc = check_draft(draft, ukc)
    z = np.asarray(getattr(depth, "values", depth), dtype=float)
    values = np.asarray(getattr(cost, "values", cost), dtype=float)
    if z.shape != values.shape:
        raise ChartError(
            f"depth has shape {z.shape} but the cost {values.shape}; resample it onto "
            "the chart with seaway.depth.depth_on_grid"
        )
    with np.errstate(invalid="ignore"):
        shallow = ~(z >= draft + ukc)
    out = np.where(shallow, np.inf, values)
    if hasattr(cost, "dims"):
        out = cost.copy(data=out.astype(cost.dtype if cost.dtype.kind == "f" else float))
        out.attrs = dict(cost.attrs, draft_m=draft, ukc_m=ukc)
    return out


def too_shallow(depth, rc, draft, ukc) -> list:
    """Why pixel rc is too shallow (a sentence in a list), or [] if it is deep enough."""
    z = float(np.asarray(getattr(depth, "values", depth))[rc])
    if not np.isfinite(z):
        return ["depth unknown (no bathymetry there)"]
    if z <= 0:
        return [f"land in the bathymetry (elevation {-z:+.0f} m)"]
    if z < draft + ukc:
        return [f"too shallow: depth {z:.1f} m < draft {draft:g} m + UKC {ukc:g} m"]
    return []


def deepest_way(cost, land, depth, start, end):
    """The deepest water a ship can sail from start to end through the pixels `cost` lets it
    enter: the largest d such that pixels with depth >= d join the two ends (4-connected: the
    engine never steps across a corner of an impassable pixel, so this is exactly the set its
    routes can use), or None when the chart's cost alone keeps them apart. Bisection over the
    chart's depths with scipy.ndimage.label."""
    from scipy import ndimage

    chart = as_chart(cost, land=land)
    a, b = locate(chart, start, "start"), locate(chart, end, "end")
    ok = np.isfinite(chart.values) & (chart.values >= 0)
    if chart.land is not None:
        ok &= chart.land == 0
    z = np.where(ok, np.asarray(getattr(depth, "values", depth), dtype=float), np.nan)

    def joined(d):
        lab, _ = ndimage.label(z >= d)
        return lab[a] > 0 and lab[a] == lab[b]

    levels = np.unique(z[np.isfinite(z)])
    if levels.size == 0 or not joined(levels[0]):
        return None
    lo, hi = 0, levels.size - 1  # joined(levels[lo]) holds
    while lo < hi:
        mid = (lo + hi + 1) // 2
        lo, hi = (mid, hi) if joined(levels[mid]) else (lo, mid - 1)
    return float(levels[lo])
