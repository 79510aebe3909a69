"""Ice and weather in one voyage (OpenForecast.route with `ice`): the ice as a season (a chart is
taken as valid from the departure for the whole voyage, said), routed with the forecast at the
class's speed in the ice (seaway.weather.route_ice_weather)."""

from __future__ import annotations

import dataclasses

import numpy as np
import xarray as xr

from ..errors import ChartError
from ..ice.classes import get_class
from ..ice.seasongrid import SeasonGrid
from ..weather import route_ice_weather
from .chart import OpenChart
from .season import OpenSeason

#: The layers of an ice chart a voyage through ice and weather reads.
ICE_LAYERS = ("CT", "CA", "SA", "CB", "SB", "CC", "SC", "thickness", "land", "off_chart")


def ice_season(ice, ice_class, notes):
    """The ice as a SeasonGrid: a season as it is, or one chart (an OpenChart) to be taken as
    valid from the departure (a Dataset with its date; ice_season_from() makes it a season)."""
    if isinstance(ice, OpenSeason):
        return ice.grid
    if isinstance(ice, SeasonGrid):
        return ice
    if not isinstance(ice, OpenChart):
        raise ChartError(f"ice must be an OpenChart, OpenSeason or SeasonGrid, got {type(ice).__name__}")
    notes += [n for n in ice.notes if n not in notes]
    layers = ice.layers
    if (
        ice.projection is not None
        or layers is None
        or "CT" not in layers
        or not ({"SA", "thickness"} & set(layers))
    ):
        raise ChartError(
            f"{ice.source}: a route through ice and weather needs an ice chart on a lat/lon "
            "grid with CT and SA or a thickness (SIGRID-3, NSIDC, a season NetCDF); "
            "leave the chart out to route on the forecast's own grid"
        )
    one = layers[[k for k in ICE_LAYERS if k in layers]].drop_vars("time", errors="ignore")
    one.attrs["date"] = ice.date or ""
    return _OneChart(one)


class _OneChart:
    """One ice chart waiting for the departure to become a season (see as_season)."""

    def __init__(self, ds):
        self.ds = ds
        self.template = ds["CT"]

    def as_season(self, departure, notes) -> SeasonGrid:
        ice = self.ds.copy()
        date = ice.attrs.pop("date", "")
        notes.append(
            f"the ice chart{' of ' + date if date else ''} is taken as valid from the "
            "departure for the whole voyage (persistence of the ice)"
        )
        return SeasonGrid(ice.expand_dims(time=[np.datetime64(departure, "ns")]))


def forecast_ice(ds, dry, notes):
    """The forecast's own ice (its roles ice_concentration and, if it has it, ice_thickness: a
    coupled ice-ocean model's aice and hice) as a season of charts on its grid, one per frame;
    land where the forecast has no field (`dry`). Without a thickness the ice is taken as thick
    first-year ice (WMO 93), said."""
    conc = ds["ice_concentration"]
    if "time" not in conc.dims:
        conc = conc.expand_dims(time=[np.datetime64("1970-01-01", "ns")])
    scale = 0.1 if str(conc.attrs.get("units", "")).strip() in ("%", "percent") else 10.0
    ct = np.clip(conc.values.astype(float) * scale, 0.0, 10.0)
    layers = {"CT": (conc.dims, ct)}
    if "ice_thickness" in ds:
        h = ds["ice_thickness"]
        h = h.transpose(*conc.dims) if "time" in h.dims else h
        layers["thickness"] = (conc.dims, np.broadcast_to(np.asarray(h.values, float), ct.shape))
        how = "its sea-ice concentration and thickness, frame by frame"
    else:
        layers["SA"] = (conc.dims, np.where(ct > 0, 93.0, np.nan))
        how = "its sea-ice concentration frame by frame, the ice taken as thick first-year (WMO 93): it gives no thickness"
    season = xr.Dataset(layers, coords={d: conc[d] for d in conc.dims})
    notes.append(f"the forecast's own ice prices the voyage: {how} ({conc.sizes['time']} frames)")
    return SeasonGrid(season, land=dry)


def route_ice_weather_voyage(
    season, ds, start, end, ice_class, vessel, fc, persist, source, notes, say, **common
):
    """The quickest route through the ice (`season`) and the forecast `ds` for `ice_class`: at the
    ship's ice curve where it has one, else its class's model."""
    if isinstance(season, _OneChart):
        season = season.as_season(fc.departure, notes)
    cls = get_class(ice_class)
    curve = getattr(vessel, "ice_curve", None)
    if curve is not None:
        model, common["speed"] = curve.describe(), curve
    else:
        model = (
            "IMO POLARIS speed limits" if cls.system in ("IACS", "FSICR") else "Andreeva 2021's V = F x V0"
        )
        common["speed"] = "class"
    say(f"routing {cls.name} through the ice ({model}) and the forecast")
    r = route_ice_weather(
        season,
        ds,
        start,
        end,
        ice_class=cls.name,
        vessel=vessel,
        departure=fc.departure,
        persist=persist,
        source=source,
        **common,
    )
    return dataclasses.replace(r, notes=tuple(r.notes) + (f"speed in ice: {model} ({cls.name})",))
