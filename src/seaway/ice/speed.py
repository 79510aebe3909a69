"""A ship's speed in the ice of a chart, for the times of a route (``seaway route --speed KN`` on
an ice chart, Route.with_ice_speed): never the open-water speed through ice.

The model depends on the class (seaway.ice.classes):

* Russian Register classes and 'none': Andreeva 2021, V = F x V0 with F = f1 x f2
  (seaway.ice.andreeva; f3 = 1: no fairway is charted). f2 = 1 - h / h_pass, h_pass the class's
  Table-1 thickness (Grinyak et al. 2022); h the chart's ice thickness (a `thickness` or CF
  `sea_ice_thickness` layer) where it has one, else the typical thickness of the governing
  stage, the upper end of its WMO range by default (conservative: thin first-year 0.7 m,
  medium 1.2 m, thick 2.0 m; seaway.ice.andreeva.stage_thickness), fast ice of unknown stage
  taking its stated stage (seaway.ice.forms). Ice free and open water (CT 0, 01, 02) give
  h = 0. f2 = 0, hence no speed, where the ice is at least as thick as h_pass: the model gives
  no independent way there (an icebreaker's escort). f1 = 1 - d / Z (Andreeva's depth factor,
  survey correction dL = 0) when a depth raster and the draft are given, else 1. The
  concentration is not a term of the model.
* IACS Polar Classes and Finnish-Swedish classes: IMO POLARIS (MSC.1/Circ.1519,
  seaway.ice.polaris): V0 in normal operation, the circular's speed limit under elevated risk
  (PC1 11 kn, PC2 8 kn, PC3-PC5 5 kn, PC6-PC7 3 kn; classes below PC7 have no such level), no
  speed under special consideration.

Land and pixels off the chart have no speed. The result names its model (attribute ``model``),
which every output of a route timed with it repeats."""

from __future__ import annotations

import numpy as np

from . import andreeva
from .classes import get_class
from .forms import DEFAULT_FAST_ICE
from .impact import governing_stage
from .polaris import SPEED_LIMIT_KN, polaris_chart

THICKNESS_NAMES = ("thickness", "ice_thickness")


def ice_speed(
    ds, ice_class, v0_kn, *, fast_ice=DEFAULT_FAST_ICE, stage_thickness="upper", depth=None, draft=None
):
    """The speed (knots) of an `ice_class` ship at open-water speed `v0_kn` in each pixel of the
    ice chart `ds` (SIGRID-style CT/SA/... and land, or a chart with stage_of_development and
    sea_ice_concentration), as a DataArray on the chart's grid whose attribute ``model`` names
    the model (see the module). depth (m, positive down, on the same grid) and draft (m) add
    Andreeva's depth factor f1 for Register classes."""
    cls = get_class(ice_class)
    v0 = float(v0_kn)
    if not v0 > 0:
        raise ValueError(f"the open-water speed must be > 0 knots, got {v0_kn!r}")
    chart = _as_sigrid(ds)
    blocked = np.asarray(chart["land"].values, bool) if "land" in chart else np.zeros(chart["CT"].shape, bool)
    if "off_chart" in chart:
        blocked |= np.asarray(chart["off_chart"].values, bool)
    if cls.system in ("IACS", "FSICR"):
        speed = np.asarray(polaris_chart(chart, cls.name, v0_kn=v0)["speed_kn"].values, float)
        limit = SPEED_LIMIT_KN.get(cls.polaris_class)
        elevated = f"{min(v0, limit):g} kn under elevated risk" if limit else "no elevated-risk level"
        model = (
            f"IMO POLARIS (MSC.1/Circ.1519), {cls.polaris_class} row: {v0:g} kn in normal "
            f"operation, {elevated}, none under special consideration"
        )
    else:
        h, whence = _thickness(chart, fast_ice, stage_thickness)
        ct = np.asarray(chart["CT"].values, float)
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
    if "CT" in ds and "SA" in ds:
        return ds
    stage = ds["stage_of_development"]
    ct = (
        ds["sea_ice_concentration"]
        if "sea_ice_concentration" in ds
        else stage.copy(data=np.where(np.asarray(stage.values) == 55, 0.0, 10.0))
    )
    ct = ct.where(stage != 55, 0.0)
    return ds.assign(CT=ct, CA=ct, SA=stage.where(stage != 55))


def _thickness(chart, fast_ice, rule):
    """(h in m, where it comes from) for f2."""
    for name in THICKNESS_NAMES:
        if name in chart:
            return np.asarray(chart[name].values, float), f"the chart's {name}"
    for name, v in chart.data_vars.items():
        if v.attrs.get("standard_name") == "sea_ice_thickness":
            return np.asarray(v.values, float), f"the chart's {name}"
    stage = governing_stage(chart, fast_ice=fast_ice)
    end = "upper end" if rule == "upper" else "middle"
    return andreeva.stage_thickness(stage, rule), f"the {end} of the governing stage's WMO range"


__all__ = ["ice_speed", "THICKNESS_NAMES"]
