"""What the maps of a weather voyage draw (seaway route --forecast ... --plot/--out .html): the
field the ship meets at its departure (significant wave height, else wind speed, else current
speed), read off the route's own model (its ForecastGrid, interpolated between frames to the
departure as the engine reads it); the ice chart valid at the departure in the WMO colour code
(a SIGRID-3 chart by its governing stage, seaway.ice.governing_stage, as the maps of ice-only
routes; a forecast's own ice by total concentration); and the pixels no chart polygon covers as
off chart, never as land (the voyage treats them as closed, the map says why)."""

from __future__ import annotations

import dataclasses

import numpy as np

from ..ice.colours import classes
from ..ice.impact import governing_stage

#: The weather field drawn, first found first: (label, unit, roles whose magnitude it is).
FIELDS = (
    ("significant wave height", "m", ("wave_height",)),
    ("wind speed", "m/s", ("wind_speed",)),
    ("current speed", "m/s", ("current_east", "current_north")),
)
OFF_CHART_COLOUR = "#e4e4e4"  # light grey, hatched: lighter than fast ice's grey
OFF_CHART_LABEL = "off chart: no ice chart polygon (closed to the voyage)"
WEATHER_CMAP = "Blues"  # the sea's colours: never taken for WMO ice classes on these maps


@dataclasses.dataclass
class VoyageLayers:
    """The layers of a weather voyage's map, on the route's chart grid."""

    field: np.ndarray | None  # the weather at departure, NaN on land, off chart and under ice
    label: str  # what `field` is: quantity (unit) at departure, time
    ice: np.ndarray | None  # values to colour by the WMO code (NaN: no ice drawn)
    code: str | None  # "stage" or "concentration"
    off_chart: np.ndarray  # pixels no chart polygon covers (not land)
    land: np.ndarray  # the land drawn: the route's land without the off-chart pixels
    ice_date: str = ""


def voyage_layers(route) -> VoyageLayers | None:
    """The layers of a route found through a forecast (its model carries a ForecastGrid on the
    route's grid), or None for any other route."""
    fc = getattr(route.model, "forecast", None)
    chart = route.chart
    if fc is None or not hasattr(fc, "arrays") or tuple(fc.shape) != tuple(chart.shape):
        return None
    land = np.zeros(chart.shape, bool) if chart.land is None else np.asarray(chart.land, bool)
    off = np.zeros(chart.shape, bool)
    ice, code, date = None, None, ""
    season = getattr(route.model, "season", None)
    if season is not None and tuple(season.shape) == tuple(chart.shape):
        ice, code, off, date = _ice_at(season, fc.departure, chart)
    land = land & ~off
    field, label = weather_at_departure(fc)
    if field is not None:
        hidden = land | off | np.asarray(fc.dry, bool)
        if ice is not None:
            hidden |= np.isfinite(ice)
        field = np.where(hidden, np.nan, field)
    return VoyageLayers(field, label, ice, code, off, land, date)


def weather_at_departure(fc) -> tuple[np.ndarray | None, str]:
    """(the forecast's main field at the departure, linear between frames as the engine reads
    it; its label with unit and time), or (None, "") if it has none of FIELDS."""
    for name, unit, roles in FIELDS:
        if all(r in fc.arrays for r in roles):
            parts = [_at_departure(fc, fc.arrays[r]) for r in roles]
            value = parts[0] if len(parts) == 1 else np.hypot(*parts)
            when = "" if fc.departure is None else f", {_iso(fc.departure)} UTC"
            return value.astype(float), f"{name} ({unit}) at departure{when}"
    return None, ""


def _at_departure(fc, a) -> np.ndarray:
    """A (frames, rows, cols) field at the departure (hour 0): frames are first_h + k step_h."""
    k = float(np.clip(-fc.first_h / fc.step_h, 0, fc.frames - 1))
    lo = int(np.floor(k))
    hi = min(lo + 1, fc.frames - 1)
    w = k - lo
    return (1 - w) * a[lo].astype(float) + w * a[hi].astype(float)


def _iso(t) -> str:
    return str(np.datetime_as_string(np.datetime64(t, "m"), unit="m")).replace("T", " ")


def _ice_at(season, departure, chart):
    """(ice values, code, off-chart mask, chart date) of the chart valid at `departure`."""
    try:
        _, i = season.departure_frames(departure)
    except ValueError:
        i = 0
    ds = season.ds.isel(time=max(i, 0))
    dims = season.template.dims
    ds = ds.transpose(*dims, ...)
    off = np.zeros(chart.shape, bool)
    if "off_chart" in ds:
        off = np.asarray(ds["off_chart"].values, bool)
        if "land" in ds:
            off &= ~np.asarray(ds["land"].values, bool)
        off &= ~_coast_land(chart)
    date = str(np.datetime_as_string(ds["time"].values, unit="m")).replace("T", " ") if "time" in ds else ""
    if "SA" in ds and "CA" in ds:  # an ice service's chart: the governing stage, as ice-only maps
        stage = np.asarray(governing_stage(ds).values, float)
        return np.where(stage == 55, np.nan, stage), "stage", off, date
    ct = np.asarray(ds["CT"].values, float)
    return np.where(ct > 0, ct, np.nan), "concentration", off, date


def _coast_land(chart) -> np.ndarray:
    """The package's coastline (global-land-mask) at the chart's pixel centres: land the voyage
    also closed, drawn as land even where no chart polygon is."""
    from global_land_mask import globe

    if not chart.geographic:
        return np.zeros(chart.shape, bool)
    la, lo = np.meshgrid(np.asarray(chart.lat, float), np.asarray(chart.lon, float), indexing="ij")
    return np.asarray(globe.is_land(la, (lo + 180.0) % 360.0 - 180.0), bool)


def voyage_rgba(v: VoyageLayers) -> tuple[np.ndarray, str, list]:
    """The HTML map's chart image of a weather voyage (seaway.output.webmap): (RGBA uint8 on
    the chart's grid, the layer's name, legend rows [(label, rgb)]); land is painted after."""
    from matplotlib import colormaps

    rgba = np.zeros(v.land.shape + (4,), np.uint8)
    legend, names = [], []
    if v.field is not None and np.isfinite(v.field).any():
        ok = np.isfinite(v.field)
        lo, hi = float(v.field[ok].min()), float(v.field[ok].max())
        cmap = colormaps[WEATHER_CMAP]
        rgba[ok] = (cmap((v.field[ok] - lo) / (hi - lo or 1.0)) * 255).astype(np.uint8)
        quantity = v.label.split(" at departure")[0]
        legend += [
            (f"{quantity}: {x:.3g}", tuple(int(c * 255) for c in cmap(f)[:3])) for x, f in ((lo, 0), (hi, 1))
        ]
        names.append(f"{v.label} ({lo:.3g} light to {hi:.3g} dark)")
    if v.ice is not None and np.isfinite(v.ice).any():
        index, table = classes(v.ice, v.code)
        shown = (index >= 0) & ~v.land & ~v.off_chart
        colours = np.array([rgb for _, rgb in table], np.uint8).reshape(-1, 3)
        rgba[shown, :3], rgba[shown, 3] = colours[index[shown]], 255
        legend += [(f"ice: {table[k][0]}", table[k][1]) for k in np.unique(index[shown])]
        by = "stage of development" if v.code == "stage" else "total concentration"
        names.append(f"ice: WMO colour code by {by}")
    if v.off_chart.any():
        grey = tuple(int(OFF_CHART_COLOUR[i : i + 2], 16) for i in (1, 3, 5))
        rgba[v.off_chart] = list(grey) + [255]
        legend.append((OFF_CHART_LABEL, grey))
    return rgba, "; ".join(names) or "no weather field", legend
