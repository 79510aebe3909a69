"""A ship's speed in the ice of a chart, for the times of a route (OpenChart.route, seaway route on
an ice chart, Route.with_ice_speed): never the open-water speed through ice.

The model, by what the ship gives (seaway.vessel.Vessel):

* Its ice curve (IceCurve: speed in level ice against thickness, from ice trials or model
  tests): V = v(h_eq), at most the open-water speed, with the equivalent thickness h_eq = C/10 x h
  (C the total concentration in tenths, h the ice's thickness; the concentration spreads the same
  ice over the area, after the equivalent ice thickness of Baltic ship-speed studies, e.g.
  Loptien and Axell 2014), and where the chart gives a ridged fraction r (0-1, a layer
  `ridged_fraction`) h_eq x (1 + r): ridged ice taken as twice the level thickness over its area
  (an assumption). No speed of its own beyond the curve's last point.
* No curve, a Russian Register class (or 'none'): Andreeva 2021, V = F x V0 with F = f1 x f2
  (seaway.ice.andreeva; f3 = 1: no fairway is charted); f2 = 1 - h / h_pass, h_pass the class's
  Table-1 thickness (Grinyak et al. 2022); f1 = 1 - d / Z with a depth raster and the draft. The
  concentration is not a term of the model.
* No curve, an IACS Polar Class or a Finnish-Swedish class: IMO POLARIS (MSC.1/Circ.1519,
  seaway.ice.polaris): V0 in normal operation, the circular's speed limit under elevated risk
  (PC1 11 kn, PC2 8 kn, PC3-PC5 5 kn, PC6-PC7 3 kn), no speed under special consideration.

The thickness h: the chart's thickness (a `thickness` or CF `sea_ice_thickness` layer) where it
has one; else the governing stage's typical thickness, a stated and editable choice within its
WMO range (seaway.ice.andreeva.stage_thickness: the middle by default, "upper", "lower" or a
table {stage: m}); fast ice of unknown stage takes its stated stage (seaway.ice.forms); ice
free and open water (CT 0, 01, 02) give h = 0. Land and pixels off the chart have no speed. The
result names its model and thickness (attribute ``model``), which every output repeats."""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import SeawayError
from . import andreeva
from .classes import get_class
from .forms import DEFAULT_FAST_ICE
from .impact import governing_stage
from .polaris import SPEED_LIMIT_KN, polaris_chart

THICKNESS_NAMES = ("thickness", "ice_thickness")
#: A chart layer giving the ridged share of the ice (0-1); ridged ice counts twice (an assumption).
RIDGED = "ridged_fraction"


def ice_speed(
    ds,
    ice_class,
    v0_kn,
    *,
    curve: Any = None,
    fast_ice=DEFAULT_FAST_ICE,
    stage_thickness=andreeva.DEFAULT_STAGE_THICKNESS,
    depth=None,
    draft=None,
):
    """The speed (knots) of an `ice_class` ship at open-water speed `v0_kn` in each pixel of the
    ice chart `ds` (SIGRID-style CT/SA/... and land, or a chart with stage_of_development and
    sea_ice_concentration), as a DataArray on the chart's grid whose attribute ``model`` names
    the model and the thickness (see the module). curve: the ship's IceCurve (or any object with
    speed(h, v0_kn) and describe()); depth (m, positive down) and draft (m) add Andreeva's
    depth factor f1 for Register classes without a curve."""
    cls = get_class(ice_class)
    v0 = float(v0_kn)
    if not v0 > 0:
        raise SeawayError(f"the open-water speed must be > 0 knots, got {v0_kn!r}")
    chart = _as_sigrid(ds)
    blocked = np.zeros(chart["CT"].shape, bool)  # a new array: the chart's layers stay as they are
    for name in ("land", "off_chart"):
        if name in chart:
            blocked |= np.asarray(chart[name].values, bool)
    ct = np.asarray(chart["CT"].values, float)
    if curve is not None:
        h, whence = thickness(chart, fast_ice, stage_thickness)
        h_eq = np.where(ct == 0, 0.0, np.clip(ct, 0, 10) / 10.0 * h)
        terms = "h_eq = C/10 x h"
        if RIDGED in chart:
            h_eq = h_eq * (1.0 + np.clip(np.nan_to_num(chart[RIDGED].values), 0, 1))
            terms += " x (1 + ridged fraction; ridged ice counted twice, an assumption)"
        speed = curve.speed(h_eq, v0)
        model = f"{curve.describe()}: V = v(h_eq), at most {v0:g} kn, {terms}, h {whence}"
    elif cls.system in ("IACS", "FSICR"):
        speed = np.asarray(polaris_chart(chart, cls.name, v0_kn=v0)["speed_kn"].values, float)
        limit = SPEED_LIMIT_KN.get(cls.polaris_class)
        elevated = f"{min(v0, limit):g} kn under elevated risk" if limit else "no elevated-risk level"
        model = (
            f"IMO POLARIS (MSC.1/Circ.1519), {cls.polaris_class} row: {v0:g} kn in normal "
            f"operation, {elevated}, none under special consideration"
        )
    else:
        h, whence = thickness(chart, fast_ice, stage_thickness)
        h = np.where(ct == 0, 0.0, h)
        if cls.h_pass > 0:
            f = andreeva.f2(h, cls.h_pass)
            terms = f"f2 = 1 - h / {cls.h_pass:g} m ({cls.name}, Grinyak et al. 2022 Table 1), h {whence}"
        else:  # not ice-strengthened: ice-free water only
            f = np.where(h == 0, 1.0, 0.0)
            terms = f"f2 = 1 in ice-free water, 0 in ice (a ship not ice-strengthened), h {whence}"
        if depth is not None and draft is not None:
            f = f * andreeva.f1(float(draft), np.asarray(getattr(depth, "values", depth), float))
            terms += f"; f1 = 1 - {float(draft):g} m / depth (survey correction dL = 0)"
        speed = f * v0
        model = f"Andreeva 2021: V = F x V0, V0 {v0:g} kn, F = f1 x f2, {terms}"
    speed = np.where(blocked | ~np.isfinite(speed), 0.0, speed)
    out = chart["CT"].copy(data=speed).rename("ice_speed")
    out.attrs = {
        "long_name": "ship speed in the ice",
        "units": "knot",
        "model": model,
        "v0_kn": v0,
        "ice_class": cls.name,
    }
    return out


def _as_sigrid(ds):
    """A SIGRID-style view (CT, CA, SA, land) of a chart with stage_of_development and
    sea_ice_concentration (seaway.samples.kara_sea()); SIGRID charts as they are."""
    if "CT" in ds and ("SA" in ds or any(n in ds for n in THICKNESS_NAMES)):
        return ds  # SIGRID-style, or a concentration with its thickness (an ocean model's ice)
    stage = ds["stage_of_development"]
    ct = (
        ds["sea_ice_concentration"]
        if "sea_ice_concentration" in ds
        else stage.copy(data=np.where(np.asarray(stage.values) == 55, 0.0, 10.0))
    )
    ct = ct.where(stage != 55, 0.0)
    return ds.assign(CT=ct, CA=ct, SA=stage.where(stage != 55))


def thickness(chart, fast_ice=DEFAULT_FAST_ICE, rule=andreeva.DEFAULT_STAGE_THICKNESS):
    """(h in m on the chart's grid, where it comes from in words): the chart's thickness layer,
    else the governing stage's thickness under `rule` (seaway.ice.andreeva.stage_thickness)."""
    for name in THICKNESS_NAMES:
        if name in chart:
            return np.asarray(chart[name].values, float), f"the chart's {name}"
    for name, v in chart.data_vars.items():
        if v.attrs.get("standard_name") == "sea_ice_thickness":
            return np.asarray(v.values, float), f"the chart's {name}"
    stage = governing_stage(_as_sigrid(chart), fast_ice=fast_ice)
    return andreeva.stage_thickness(stage, rule), andreeva.stage_thickness_words(stage, rule)


__all__ = ["ice_speed", "thickness", "THICKNESS_NAMES", "RIDGED"]
