"""Synthetic seasons: a week of daily ice charts with a retreating edge, and planar seasons
by WMO stage (moved from ice/test_ice_season.py)."""

import numpy as np
import xarray as xr

DAY0 = np.datetime64("2026-07-01T00")


def retreating_edge(days=7, edge0=72.0, per_day=0.6):
    """Synthetic daily charts on a lat/lon grid (70-78 N, 60-80 E, 0.2 deg): the ice edge at
    latitude edge0 + per_day x day retreats north; north of it 3 deg of thin first-year ice
    (4/10 near the edge, 7/10 beyond), then medium first-year 8/10. Land: a Novaya-Zemlya-like
    bar at 60-62 E north of 73 N."""
    lat = np.round(np.arange(78.0, 69.99, -0.2), 6)
    lon = np.round(np.arange(60.0, 80.01, 0.2), 6)
    la, lo = np.meshgrid(lat, lon, indexing="ij")
    ct, sa = [], []
    for d in range(days):
        beyond = la - (edge0 + per_day * d)
        c = np.where(beyond < 0, 0.0, np.where(beyond < 1, 4.0, np.where(beyond < 3, 7.0, 8.0)))
        s = np.where(beyond < 0, np.nan, np.where(beyond < 3, 87.0, 91.0))
        ct.append(c)
        sa.append(s)
    land = (lo <= 62.0) & (la >= 73.0)
    time = DAY0 + np.arange(days) * np.timedelta64(1, "D")
    return xr.Dataset(
        {
            "CT": (("time", "lat", "lon"), np.array(ct)),
            "SA": (("time", "lat", "lon"), np.array(sa)),
            "land": (("time", "lat", "lon"), np.broadcast_to(land, (days,) + land.shape)),
        },
        coords={"time": time, "lat": lat, "lon": lon},
    )


CHANNEL_LAT = np.round(np.arange(71.2, 69.99, -0.02), 6)  # 61 rows, 2.22 km apart
CHANNEL_LON = np.round(np.arange(60.0, 66.001, 0.05), 6)  # 121 columns, 1.86 km apart at 70.5 N


def channel_season(ice, days=3, wall=None):
    """Daily charts (from DAY0) of a channel of open water at 70.40-70.60 N (pixel centres)
    between land to the north and south, 60-66 E. ice: [(day, (lat0, lat1, lon0, lon1), CT,
    SA), ...]: ice on that day's chart over the pixels whose centres lie in the box. wall: a
    longitude where land closes the channel (two separate water bodies)."""
    la, lo = np.meshgrid(CHANNEL_LAT, CHANNEL_LON, indexing="ij")
    land = (la > 70.6001) | (la < 70.3999)
    if wall is not None:
        land |= np.isclose(lo, wall)
    ct = np.zeros((days,) + la.shape)
    sa = np.full((days,) + la.shape, np.nan)
    for day, (a, b, c, d), conc, stage in ice:
        box = (la >= a - 1e-6) & (la <= b + 1e-6) & (lo >= c - 1e-6) & (lo <= d + 1e-6)
        ct[day][box], sa[day][box] = conc, stage
    ct[:, land] = np.nan
    time = DAY0 + np.arange(days) * np.timedelta64(1, "D")
    return xr.Dataset(
        {
            "CT": (("time", "lat", "lon"), ct),
            "SA": (("time", "lat", "lon"), sa),
            "land": (("time", "lat", "lon"), np.broadcast_to(land, ct.shape)),
        },
        coords={"time": time, "lat": CHANNEL_LAT, "lon": CHANNEL_LON},
    )


def planar_season(stage, ct=None, hours=None, dx=10.0):
    """A season Dataset on a planar grid of dx-km pixels: stage (K, R, C), charts at `hours`."""
    k, rows, cols = stage.shape
    ct = np.where(stage == 55, 0.0, 9.0) if ct is None else ct
    hours = np.arange(k) * 24.0 if hours is None else np.asarray(hours, float)
    time = DAY0 + (hours * 3600).astype("timedelta64[s]")
    sa = np.where(stage == 55, np.nan, stage).astype(float)
    return xr.Dataset(
        {
            "CT": (("time", "y", "x"), ct.astype(float)),
            "SA": (("time", "y", "x"), sa),
            "land": (("time", "y", "x"), np.zeros(stage.shape, bool)),
        },
        coords={"time": time, "y": dx * np.arange(rows)[::-1], "x": dx * np.arange(cols)},
    )


#: A polar stereographic projection (NSIDC's EPSG:3413 parameters on a sphere) for projected seasons.
POLAR = "+proj=stere +lat_0=90 +lat_ts=70 +lon_0=-45 +R=6371000 +units=m +no_defs"
POLAR_CENTRE = (75.0, 60.0)  # lat, lon of pixel (15, 25) of projected_season()


def projected_season(rows=31, cols=51, dx_m=10_000.0, wall=(24, 26), open_day=2, days=3):
    """Daily charts (from DAY0) on a polar stereographic grid (POLAR) of dx_m pixels, its axes in
    metres, with a CF grid mapping (the WKT pyproj writes) named by CT and SA: open water but for
    a wall of thick first-year ice (SA 93, 9/10) over columns wall[0]..wall[1] (all rows) until
    day `open_day`, when it clears. Pixel (15, 25) is centred on POLAR_CENTRE; y grows with the
    row, x with the column."""
    import pyproj

    crs = pyproj.CRS.from_proj4(POLAR)
    fwd = pyproj.Transformer.from_crs("EPSG:4326", crs, always_xy=True)
    x0, y0 = fwd.transform(POLAR_CENTRE[1], POLAR_CENTRE[0])
    y = y0 + dx_m * (np.arange(rows) - 15)
    x = x0 + dx_m * (np.arange(cols) - 25)
    ct = np.zeros((days, rows, cols))
    sa = np.full((days, rows, cols), np.nan)
    ct[:open_day, :, wall[0] : wall[1] + 1], sa[:open_day, :, wall[0] : wall[1] + 1] = 9.0, 93.0
    gm = {"grid_mapping": "crs"}
    time = DAY0 + np.arange(days) * np.timedelta64(1, "D")
    return xr.Dataset(
        {
            "CT": (("time", "y", "x"), ct, gm),
            "SA": (("time", "y", "x"), sa, gm),
            "crs": ((), 0, {"crs_wkt": crs.to_wkt(), **crs.to_cf()}),
        },
        coords={
            "time": time,
            "y": ("y", y, {"standard_name": "projection_y_coordinate", "units": "m"}),
            "x": ("x", x, {"standard_name": "projection_x_coordinate", "units": "m"}),
        },
    )
