"""Built-in charts: a synthetic winter Kara Sea on the real coastline and a planar cost raster
for benchmarks; Grinyak et al. 2022's ice impact tables are re-exported from seaway.ice.impact.

The Kara Sea chart is synthetic ice (made up, but shaped like a late-winter chart: fast ice along
the coasts, a flaw polynya seaward of it, thicker first-year ice towards the north-east) laid on
the real GLOBE coastline of the `global-land-mask` package. It is a demonstration chart, not an
observation: never navigate by it."""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from ..base.fields import distance_km, gaussian, resample, smooth_noise
from ..base.memory import KARA, KARA_DAY, ROUTE, check_shape
from ..base.units import EARTH_RADIUS_KM, KM_PER_DEG  # noqa: F401 - EARTH_RADIUS_KM: part of this API
from ..errors import SeawayError
from ..ice import classes as ice_classes
from ..ice.codes import STAGE_CODES

# Grinyak et al. 2022's impact tables and ice_impact() live in seaway.ice.impact (with tables for every
# class); re-exported here so seaway.samples.ice_impact keeps working.
from ..ice.impact import ICE_IMPACT, ice_impact  # noqa: F401
from .synthetic import SYNTHETIC_END, SYNTHETIC_START, synthetic_endpoints, synthetic_sea

# The benchmark raster (synthetic_*, SYNTHETIC_*) is defined in seaway.samples.synthetic.
__all__ = [
    "kara_sea",
    "kara_season",
    "synthetic_endpoints",
    "synthetic_sea",
    "KARA_EXTENT",
    "STAGES",
    "ICE_CLASS_ALIASES",
    "SYNTHETIC_START",
    "SYNTHETIC_END",
]

#: Extent of kara_sea() in degrees: pixel edges, not centres.
KARA_EXTENT = {"lat_north": 82.0, "lat_south": 68.0, "lon_west": 50.0, "lon_east": 110.0}

#: The WMO stages of development the synthetic chart uses: code -> (name, typical thickness
#: range in m), from seaway.ice.codes. New ice and nilas are both "< 10 cm"; the chart puts new
#: ice below 5 cm.
STAGES = {c: STAGE_CODES[c] for c in (55, 81, 82, 83, 84, 85, 86, 87, 88, 89, 91, 93)}

#: Classes without a table of their own in ICE_IMPACT -> the RS class whose table they use.
ICE_CLASS_ALIASES = {n: c.rs_class for n, c in ice_classes.CLASSES.items() if n not in ICE_IMPACT}


def _grid(shape):
    rows, cols = (int(n) for n in shape)
    if rows < 2 or cols < 2:
        raise SeawayError(f"shape must be (rows, cols) with at least 2 of each, got {shape!r}")
    e = KARA_EXTENT
    dlat = (e["lat_north"] - e["lat_south"]) / rows
    dlon = (e["lon_east"] - e["lon_west"]) / cols
    lat = e["lat_north"] - (np.arange(rows) + 0.5) * dlat
    lon = e["lon_west"] + (np.arange(cols) + 0.5) * dlon
    return lat, lon


def _coarse_land_distance(shape=(380, 460), sub=4, max_km=200.0):
    """Distance (km) to the nearest land, and the land fraction within ~60 km, on a coarse grid
    (~4 km cells) whose land is 'any GLOBE land among sub x sub samples of the cell'."""
    from global_land_mask import globe

    lat, lon = _grid((shape[0] * sub, shape[1] * sub))
    land = globe.is_land(lat[:, None], lon[None, :])
    land = land.reshape(shape[0], sub, shape[1], sub).any(axis=(1, 3))
    clat, _ = _grid(shape)
    e = KARA_EXTENT
    dy = (e["lat_north"] - e["lat_south"]) / shape[0] * KM_PER_DEG
    dx = (e["lon_east"] - e["lon_west"]) / shape[1] * KM_PER_DEG * np.cos(np.radians(clat))
    return distance_km(land, dy, dx, max_km), gaussian(land.astype(float), 60.0 / dy)


def _stage_from_thickness(h, fy_lumped):
    stage = np.select(
        [h <= 0, h < 0.05, h < 0.10, h < 0.15, h < 0.30, h < 0.70, h < 1.20],
        [55, 81, 82, 84, 85, 87, 91],
        default=93,
    ).astype(np.float32)
    lump = fy_lumped & (h >= 0.30) & (h < 2.0)  # an analyst's undivided first-year ice
    stage[lump] = 86
    return stage


@lru_cache(maxsize=4)
def _kara_sea(shape):
    import xarray as xr
    from global_land_mask import globe

    lat, lon = _grid(shape)
    rows, cols = shape
    land = globe.is_land(lat[:, None], lon[None, :])

    # Smooth fields on fixed coarse grids, so every resolution shows the same ice.
    dist_c, enclosed_c = _coarse_land_distance()
    d = np.where(land, np.float32(0), resample(dist_c, rows, cols))
    enclosed = resample(enclosed_c, rows, cols)
    rng = np.random.default_rng(20210401)
    n = [resample(smooth_noise(rng, (190, 230), sigma), rows, cols) for sigma in (6, 6, 6, 6, 4, 6)]
    la, lo = lat.astype(np.float32)[:, None], lon.astype(np.float32)[None, :]
    ne = np.clip(0.55 * (la - 68) / 14 + 0.45 * (lo - 50) / 60, 0, 1)
    # Atlantic water keeps the south-east Barents Sea, west of Novaya Zemlya, thin and open.
    km2 = ((la - 70.5) * KM_PER_DEG) ** 2 + ((lo - 47) * KM_PER_DEG * np.cos(np.radians(la))) ** 2
    warm = np.exp(-km2 * (0.6 + 0.8 * n[3]) / (2 * 250.0**2))  # a ragged edge
    # Signed km east of the line along Novaya Zemlya (70.5 N 57 E to 77 N 68.5 E); < 0 on the
    # Barents side, which gets no flaw polynyas.
    coslat = np.cos(np.radians(73.7))
    ax, ay = 11.5 * coslat, 6.5  # the line's direction, in degrees of latitude
    east_km = ((lo - 57) * coslat * ay - (la - 70.5) * ax) * KM_PER_DEG / np.hypot(ax, ay)

    # Fast ice: wide along long coasts (not round small islands), wider to the north-east, and
    # filling gulfs and straits (enclosed water).
    w_fast = 5 + (25 * ne + 20 * n[0]) * (1 - warm) * np.clip(enclosed / 0.2, 0, 1)
    w_fast += 150 * np.clip((enclosed - 0.4) / 0.25, 0, 1)
    fast = ~land & (d < w_fast)
    h_fast = (1.35 + 0.5 * ne + 0.2 * (n[1] - 0.5)) * (1 - 0.4 * np.clip(d / w_fast, 0, 1))

    # Drifting ice, thicker to the north-east, with refrozen leads; a flaw polynya (open water,
    # then new ice, nilas and grey ice) where offshore winds push it off the fast ice edge.
    h_pack = (0.45 + 1.25 * ne + 0.35 * (n[2] - 0.5)) * np.clip(1 - 1.2 * warm, 0, 1)
    h_pack *= 1 - 0.75 * np.clip((n[3] - 0.8) / 0.15, 0, 1)
    active = np.clip(3 * n[4] - 1.3, 0, 1) * np.clip(0.5 + east_km / 100, 0, 1)
    e = np.maximum(d - w_fast, 0)
    open_km, ramp_km = 12 * active, 45 * active
    ramp = np.ones_like(e)
    np.divide(e - open_km, ramp_km, out=ramp, where=ramp_km > 0)
    h = np.where(fast, h_fast, h_pack * np.clip(ramp, 0, 1) ** 1.5)
    h[(h < 0.01) | land] = 0

    conc = np.where(fast, 10, (8 + 3 * n[5]) * np.clip(h / 0.15, 0, 1))
    conc = np.clip(np.rint(conc), 0, 10).astype(np.float32)
    h[conc == 0] = 0
    stage = _stage_from_thickness(h, n[5] > 0.8)
    conc[land], stage[land], h[land] = np.nan, np.nan, np.nan  # so ice_impact() gives inf
    return _dataset(xr, lat, lon, land, conc, stage, h)


def _dataset(xr, lat, lon, land, conc, stage, h):
    codes = sorted(STAGES)
    coords = {
        "lat": (
            "lat",
            lat,
            {
                "standard_name": "latitude",
                "units": "degrees_north",
                "long_name": "latitude of pixel centre",
                "axis": "Y",
            },
        ),
        "lon": (
            "lon",
            lon,
            {
                "standard_name": "longitude",
                "units": "degrees_east",
                "long_name": "longitude of pixel centre",
                "axis": "X",
            },
        ),
    }
    dims = ("lat", "lon")
    data = {
        "land": (
            dims,
            land,
            {
                "standard_name": "land_binary_mask",
                "units": "1",
                "long_name": "land (GLOBE 1 km land mask at the pixel centre)",
            },
        ),
        "sea_ice_concentration": (
            dims,
            conc,
            {
                "standard_name": "sea_ice_area_fraction",
                "units": "0.1",
                "long_name": "total ice concentration CT in tenths (0 ice free ... 10 = 10/10; NaN on land)",
            },
        ),
        "stage_of_development": (
            dims,
            stage,
            {
                "long_name": "stage of development of the ice (WMO SIGRID-3 code, SA; NaN on land)",
                "units": "1",
                "flag_values": np.array(codes, dtype=np.float32),
                "flag_meanings": " ".join(STAGES[c][0].replace(" ", "_").replace(",", "") for c in codes),
                "references": "JCOMM Technical Report 23 (SIGRID-3, v3.0)",
            },
        ),
        "ice_thickness": (
            dims,
            h,
            {
                "standard_name": "sea_ice_thickness",
                "units": "m",
                "long_name": "sea ice thickness (NaN on land)",
            },
        ),
    }
    attrs = {
        "title": "Kara Sea in late winter: synthetic ice chart on the real coastline",
        "source": "synthetic ice (deterministic smooth random fields, seaway.samples.kara_sea) on "
        "the real GLOBE coastline from the global-land-mask package",
        "comment": "A demonstration chart, not an observation; do not navigate by it. Rows run "
        "north to south (lat descending).",
        "Conventions": "CF-1.8",
    }
    return xr.Dataset(data, coords=coords, attrs=attrs)


def kara_sea(shape=(1900, 2300)):
    """A synthetic late-winter ice chart of the Kara Sea on the real coastline (xarray.Dataset).

    The grid is regular in lat/lon, 82-68 N by 50-110 E (KARA_EXTENT, pixel edges); `lat` holds
    pixel centres descending north to south (row 0 is the northern edge), `lon` ascending. At the
    default (1900, 2300) a pixel is 0.82 km north-south and 0.4-1.1 km east-west (0.75 km at
    75 N), like the ~2300 x 1900-pixel chart of Grinyak et al. 2022. Variables: land (bool, GLOBE),
    sea_ice_concentration (CT, tenths), stage_of_development (WMO SIGRID-3 codes), ice_thickness
    (m); the last three are float32 and NaN on land, so `ice_impact(ds.stage_of_development)` is
    inf there. Deterministic; cached, and each call returns its own copy.

    Example: ``ds = kara_sea(); u = ice_impact(ds.stage_of_development, "Arc7");
    seaway.route(u, (70.3, 58.5), (77.7, 103.99))``"""
    if isinstance(shape, (int, np.integer)) or len(shape) != 2:
        raise SeawayError(f"shape must be (rows, cols), got {shape!r}")
    _fits(shape, KARA + ROUTE, "the synthetic Kara Sea")
    _grid(shape)
    return _kara_sea(tuple(int(n) for n in shape)).copy(deep=True)


def _fits(shape, bytes_per_pixel, what, fix="give a smaller shape"):
    """Refuse a sample too large for the machine's memory (seaway.base.memory) before making
    it, naming a shape that fits."""
    rows, cols = (int(n) for n in shape)
    if rows >= 2 and cols >= 2:
        check_shape(rows, cols, bytes_per_pixel, what, fix, SeawayError)


def kara_season(days=7, start="2026-07-01", melt_m_per_day=0.1, melted_m=0.5, shape=(380, 460)):
    """A synthetic week (or `days`) of daily ice charts of the Kara Sea breaking up: kara_sea's
    late-winter ice thinned by `melted_m` on the first chart and `melt_m_per_day` more each
    day; ice thinner than 0.8 m opens in proportion (CT = round(CT x h / 0.8)), the stage
    follows the thickness. A season Dataset for
    seaway.icenav.season (time, lat, lon): CT (tenths), SA (WMO code, NaN where ice free),
    thickness (m), land; one chart a day at 00 UTC from `start`. Synthetic: never navigate by it."""
    import xarray as xr

    if not (isinstance(days, (int, np.integer)) and days >= 1):
        raise SeawayError(f"days must be a whole number of days >= 1, got {days!r}")
    if not (np.isfinite(melt_m_per_day) and melt_m_per_day >= 0):
        raise SeawayError(f"melt_m_per_day must be >= 0 (m of ice a day), got {melt_m_per_day!r}")
    if isinstance(shape, (int, np.integer)) or len(shape) != 2:
        raise SeawayError(f"shape must be (rows, cols), got {shape!r}")
    _fits(
        shape,
        KARA + KARA_DAY * days + ROUTE,
        f"{days} days of the synthetic Kara Sea",
        "give fewer days or a smaller shape",
    )
    ds = kara_sea(shape)
    h0, ct0 = ds.ice_thickness.values, ds.sea_ice_concentration.values
    ct, sa, h = [], [], []
    for d in range(days):
        hd = np.maximum(h0 - melted_m - melt_m_per_day * d, 0).astype(np.float32)
        c = np.rint(ct0 * np.clip(hd / 0.8, 0, 1)).astype(np.float32)
        hd[c == 0] = 0
        s = _stage_from_thickness(hd, np.zeros(hd.shape, bool))
        s[c == 0] = np.nan
        land = ds.land.values
        c[land], s[land], hd[land] = np.nan, np.nan, np.nan
        ct.append(c), sa.append(s), h.append(hd)
    dims = ("time", "lat", "lon")
    time = np.datetime64(start, "D") + np.arange(days).astype("timedelta64[D]")
    return xr.Dataset(
        {
            "CT": (dims, np.array(ct), {"units": "0.1", "long_name": "total concentration"}),
            "SA": (dims, np.array(sa), {"long_name": "stage of development (WMO code)"}),
            "thickness": (dims, np.array(h), {"units": "m", "standard_name": "sea_ice_thickness"}),
            "land": (("lat", "lon"), ds.land.values),
        },
        coords={"time": time.astype("datetime64[ns]"), "lat": ds.lat, "lon": ds.lon},
        attrs={
            "title": f"Kara Sea breaking up: {days} synthetic daily charts from {start}",
            "comment": "synthetic (seaway.samples.kara_season); do not navigate by it",
        },
    )
