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
