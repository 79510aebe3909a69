"""A route's ends on a chart file: say why an end the ship may not use is impassable (land, the
ice by its SIGRID-3 stage and concentration, off the chart, too shallow for the draft), and
find the nearest point it may use.

"Nearest point the ship may use": the pixel, by great-circle distance from the point as given,
that the ship can reach from the other end (the engine's cost field from that end, so a
snapped end never sits in a pocket cut off by land or ice); when the other end is impassable
too, the nearest passable pixel."""

from __future__ import annotations

import numpy as np

from ..base.sphere import distance_km
from ..chart.locate import locate
from ..chart.raster import as_chart
from ..engine.api import cost_field
from ..ice.codes import stage_name


def _pixel(chart, p):
    """(row, col) of the pixel holding p (lat, lon), as locate() picks it, or None off the grid."""
    g = chart.grid
    r = int(round((p[0] - g.lat0) / g.dlat))
    c = int(round(((p[1] - g.lon0) / g.dlon + 0.5) % (360.0 / abs(g.dlon)) - 0.5))
    if g.wrap:
        c %= chart.shape[1]
    rows, cols = chart.shape
    return (r, c) if 0 <= r < rows and 0 <= c < cols else None


def _km(lat, lon, p):
    return distance_km(lat, lon, p[0], p[1])


def _value(layers, name, rc):
    if layers is None or name not in layers:
        return np.nan
    v = np.asarray(layers[name].values)[rc]
    return float(v)


def describe(layers, rc, vessel, reasons=(), ice_blocks=True) -> str:
    """What makes the pixel impassable, in a navigator's words. ice_blocks: whether the chart's
    own cost forbids the pixel (else only `reasons`, e.g. too shallow, are given)."""

    parts = [f"{why}" for why in reasons]
    if not ice_blocks and parts:
        return "; ".join(parts)
    if layers is not None and "land" in layers and bool(np.asarray(layers["land"].values)[rc]):
        shelf = "ice_shelf" in layers and bool(np.asarray(layers["ice_shelf"].values)[rc])
        return "; ".join(["an ice shelf (SIGRID-3 POLY_TYPE S)" if shelf else "land"] + parts)
    if layers is not None and "off_chart" in layers and bool(np.asarray(layers["off_chart"].values)[rc]):
        return "; ".join(["off the chart: no chart polygon covers it, so its ice is unknown and "
                          "counts as impassable"] + parts)
    ice = []
    for c, s in (("CA", "SA"), ("CB", "SB"), ("CC", "SC")):
        stage, conc = _value(layers, s, rc), _value(layers, c, rc)
        if np.isfinite(stage) and conc != 0:
            share = f", {conc:g}/10" if np.isfinite(conc) else ""
            ice.append(f"{stage_name(stage)} (WMO stage {int(stage)}{share})")
    if not ice and np.isfinite(_value(layers, "stage_of_development", rc)):
        stage = _value(layers, "stage_of_development", rc)
        ice.append(f"{stage_name(stage)} (WMO stage {int(stage)})")
    ct = _value(layers, "CT", rc)
    if not np.isfinite(ct):
        ct = _value(layers, "sea_ice_concentration", rc)
    if ice or np.isfinite(ct):
        text = ", ".join(ice) if ice else "ice of unknown stage"
        if np.isfinite(ct):
            text += f", total concentration {ct:g}/10"
        who = f"an {vessel} ship" if vessel else "the ship"
        parts.insert(0, f"ice {who} may not enter: {text}")
    if not parts:
        parts.append("an impassable pixel (cost NaN or infinite)")
    return "; ".join(parts)


def check_ends(cost, land, layers, ends, *, vessel=None, snap=False, say=print,
               neighbourhood=5, reasons=None, chart_cost=None):
    """The ends (start, end) as (lat, lon), unchanged when passable; an impassable one raises
    ValueError naming why and the nearest usable point, or with snap=True is moved there (and
    `say` tells). reasons(rc) -> list of extra reasons for a pixel (e.g. too shallow);
    chart_cost: the cost before those were applied (tells whether the ice itself forbids it)."""
    chart = as_chart(cost, land=land)
    if not chart.geographic:
        return list(ends)
    names = ("start", "end")
    bad = []
    for name, p in zip(names, ends):
        try:
            locate(chart, p, name)
            bad.append(False)
        except ValueError as exc:
            if _pixel(chart, p) is None:
                raise ValueError(str(exc)) from None
            bad.append(True)
    out = list(ends)
    for k, (name, p) in enumerate(zip(names, ends)):
        if not bad[k]:
            continue
        rc = _pixel(chart, p)
        other = ends[1 - k]
        if not bad[1 - k]:  # pixels the ship can reach from the other end
            field = np.asarray(cost_field(cost, other, land=land, neighbourhood=neighbourhood))
            usable = np.isfinite(field)
            usable[_pixel(chart, other)] = True
        else:
            usable = np.isfinite(chart.values) & (chart.values >= 0)
            if chart.land is not None:
                usable &= chart.land == 0
        base = np.asarray(getattr(chart_cost, "values", chart_cost), float) if chart_cost is not None else None
        blocks = base is None or not np.isfinite(base[rc]) or (chart.land is not None and chart.land[rc])
        what = describe(layers, rc, vessel, reasons(rc) if reasons else (), blocks)
        here = f"{name} {p[0]:g},{p[1]:g} is on an impassable pixel ({what})"
        cand = np.argwhere(usable)
        if cand.size == 0:
            raise ValueError(f"{here}; no pixel of the chart is usable from the other end")
        km = _km(chart.lat[cand[:, 0]], chart.lon[cand[:, 1]], p)
        i = int(np.argmin(km))
        r, c = cand[i]
        q = (float(chart.lat[r]), float(chart.lon[c]))
        q = (q[0], (q[1] + 180.0) % 360.0 - 180.0)
        if not snap:
            raise ValueError(f"{here}; the nearest point the ship may use is {q[0]:.4f},{q[1]:.4f}, "
                             f"{km[i]:.1f} km away: give it, or pass --snap to move the {name} there")
        say(f"{here}: moved {km[i]:.1f} km to {q[0]:.4f},{q[1]:.4f} (--snap)")
        out[k] = q
    return out
