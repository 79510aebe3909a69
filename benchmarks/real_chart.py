"""A benchmark chart from real data: the GSHHG land mask at 1 arc-minute with NSIDC's passive-
microwave sea-ice concentration (G02202 v4, 2021-12-31) made an Arc7 cost chart, over the Kara
Sea, 68-81.5 N 50-105 E (810 x 3300 pixels of 1 arc-minute).

The concentration (25 km, NSIDC polar stereographic north, EPSG:3411) is read at each pixel
centre by the nearest cell; cells that NSIDC flags (coast, land, lakes, pole hole) take the
nearest measured concentration, since the land comes from GSHHG. seaway.ice.concentration
makes it an ice chart with the stage of development assumed (thick first-year ice, WMO 93: the
Kara Sea's ice at the year's end) and seaway.ice.impact prices it for an Arc7 (Grinyak et al.
2022). The data live in ../shared/data (see its README); `kara_chart()` returns None when they
are absent."""

from __future__ import annotations

import os

import numpy as np

ROOT = os.path.join(os.path.dirname(__file__), "..", "..", "shared", "data")
LAND = os.path.join(ROOT, "land", "gshhg_f_landmask_1arcmin_60N.nc")
CONC = os.path.join(ROOT, "sea_ice_concentration", "seaice_conc_daily_nh_20211231_f17_v04r00.nc")
BOX = dict(lat=(68.0, 81.5), lon=(50.0, 105.0))
#: The Kara Gate and the western approach of the Vilkitsky Strait (moved to the nearest water).
VOYAGE = ((70.34, 58.28), (77.5, 100.0))


def concentration_on(lat, lon):
    """NSIDC's concentration (0-1) at the lat/lon pixel centres: nearest 25 km cell; flagged
    cells filled with the nearest measured value."""
    import pyproj
    import xarray as xr
    from scipy import ndimage

    ds = xr.open_dataset(CONC)
    conc = np.asarray(ds["cdr_seaice_conc"].values, float)[0]
    x, y = np.asarray(ds["xgrid"].values, float), np.asarray(ds["ygrid"].values, float)
    crs = ds["projection"].attrs["proj4text"]
    flagged = ~(conc <= 1.0)
    _, (iy, ix) = ndimage.distance_transform_edt(flagged, return_indices=True)
    filled = conc[iy, ix]
    to_xy = pyproj.Transformer.from_crs("EPSG:4326", crs, always_xy=True)
    lo, la = np.meshgrid(lon, lat)
    px, py = to_xy.transform(lo, la)
    col = np.clip(np.rint((px - x[0]) / (x[1] - x[0])).astype(int), 0, x.size - 1)
    row = np.clip(np.rint((py - y[0]) / (y[1] - y[0])).astype(int), 0, y.size - 1)
    return filled[row, col]


def kara_chart():
    """(Arc7 cost DataArray on lat/lon, the assumptions as sentences), or None without the data."""
    if not (os.path.exists(LAND) and os.path.exists(CONC)):
        return None
    import xarray as xr

    from seaway.ice.concentration import concentration_chart
    from seaway.ice.impact import chart_impact

    land = xr.open_dataset(LAND)["land"].sel(lat=slice(*BOX["lat"]), lon=slice(*BOX["lon"]))
    lat, lon = land["lat"].values, land["lon"].values
    conc = xr.DataArray(
        concentration_on(lat, lon),
        coords={"lat": lat, "lon": lon},
        dims=("lat", "lon"),
        name="cdr_seaice_conc",
        attrs={"standard_name": "sea_ice_area_fraction", "units": "1"},
    )
    ice, assumed = concentration_chart(conc, land=land.values.astype(bool))
    cost = chart_impact(ice, "Arc7")
    return cost, list(assumed) + list(cost.attrs.get("assumptions", ()))


def voyage_pixels(cost):
    """The benchmark voyage's ends as pixels (row, col): each the water pixel nearest the named
    point (Kara Gate, Vilkitsky Strait west)."""
    water = np.argwhere(np.isfinite(cost.values))
    lat, lon = cost["lat"].values, cost["lon"].values
    out = []
    for la, lo in VOYAGE:
        r, c = np.abs(lat - la).argmin(), np.abs(lon - lo).argmin()
        out.append(tuple(map(int, water[np.argmin((water[:, 0] - r) ** 2 + (water[:, 1] - c) ** 2)])))
    return tuple(out)
