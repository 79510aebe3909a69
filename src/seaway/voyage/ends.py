"""A route's ends on a chart file: say why an end the ship may not use is impassable (land, the
ice by its SIGRID-3 stage and concentration, off the chart, too shallow for the draft), and
find the nearest point it may use.

"Nearest point the ship may use": the pixel, by great-circle distance from the point as given,
in water that joins both ends (seaway.engine.snap.snap_ends: the engine's cost field, so a
snapped end never sits in a pocket cut off by land or ice, and two impassable ends move into
the same water); --snap moves an end at most --snap-km."""

from __future__ import annotations

import numpy as np

from ..base.sphere import distance_km
from ..chart.raster import as_chart
from ..engine.snap import DEFAULT_SNAP_KM, SnapError, snap_ends
from ..ice.classes import with_article
from ..ice.codes import stage_name
from ..ice.forms import DEFAULT_FAST_ICE, fast_ice_mask, fast_ice_stage, ice_words


def _value(layers, name, rc):
    if layers is None or name not in layers:
        return np.nan
    v = np.asarray(layers[name].values)[rc]
    return float(v)


def describe(layers, rc, vessel, reasons=(), ice_blocks=True, fast_ice=DEFAULT_FAST_ICE) -> str:
    """What makes the pixel impassable, in a navigator's words. ice_blocks: whether the chart's
    own cost forbids the pixel (else only `reasons`, e.g. too shallow, are given); fast_ice: the
    rule that gives fast ice of unknown stage its stage (seaway.ice.forms), named for it."""

    parts = [f"{why}" for why in reasons]
    if not ice_blocks and parts:
        return "; ".join(parts)
    if layers is not None and "land" in layers and bool(np.asarray(layers["land"].values)[rc]):
        shelf = "ice_shelf" in layers and bool(np.asarray(layers["ice_shelf"].values)[rc])
        return "; ".join(["an ice shelf (SIGRID-3 POLY_TYPE S)" if shelf else "land"] + parts)
    if layers is not None and "off_chart" in layers and bool(np.asarray(layers["off_chart"].values)[rc]):
        return "; ".join(
            ["off the chart: no chart polygon covers it, so its ice is unknown and counts as impassable"]
            + parts
        )
    ice = []
    fast = _fast_words(layers, rc, fast_ice)
    if fast:
        ice.append(fast)
    for c, s in (("CA", "SA"), ("CB", "SB"), ("CC", "SC")) if not fast else ():
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
        who = f"{with_article(vessel)} ship" if vessel else "the ship"
        parts.insert(0, f"ice {who} may not enter: {text}")
    if not parts:
        parts.append("an impassable pixel (cost NaN or infinite)")
    return "; ".join(parts)


def _fast_words(layers, rc, fast_ice) -> str:
    """Fast ice at pixel rc in words (its stage, or the rule's for fast ice of unknown stage), or
    "" where the pixel holds no fast ice."""
    if layers is None or "SA" not in layers or "FA" not in layers:
        return ""
    if not bool(fast_ice_mask(layers)[rc]):
        return ""
    code, _, where = fast_ice_stage(layers, fast_ice)
    assumed = bool(np.asarray(where)[rc])
    stage = (np.nan if code is None else float(code)) if assumed else _value(layers, "SA", rc)
    return ice_words(stage, True, assumed, "WMO stage")


def check_ends(
    cost,
    land,
    layers,
    ends,
    *,
    vessel=None,
    snap=False,
    snap_km=DEFAULT_SNAP_KM,
    say=print,
    neighbourhood=5,
    reasons=None,
    chart_cost=None,
    to_user=None,
    asked=None,
    why=None,
    fast_ice=DEFAULT_FAST_ICE,
):
    """The ends (start, end) the route uses (seaway.engine.snap.snap_ends), and the sentences
    saying how they moved. An impassable end raises ValueError naming why and the nearest
    usable point joined to the other end, or with snap=True is moved there when that is at most
    `snap_km` away (and `say` tells). reasons(rc) -> list of extra reasons for a pixel (e.g. too
    shallow); chart_cost: the cost before those were applied (tells whether the ice itself
    forbids it); to_user(point) -> (lat, lon): how a chart point (a projected chart's pixel)
    reads for the user (default: as it is); asked: the ends as the user gave them (default
    `ends`), for the messages; why(row, col) -> str: what makes a pixel impassable (default
    from the chart's layers, as describe() says it)."""
    chart = as_chart(cost, land=land)
    base = None if chart_cost is None else np.asarray(getattr(chart_cost, "values", chart_cost), float)

    def described(r, c):
        blocks = base is None or not np.isfinite(base[r, c]) or (chart.land is not None and chart.land[r, c])
        return describe(layers, (r, c), vessel, reasons((r, c)) if reasons else (), blocks, fast_ice)

    show = to_user or (lambda p: p)
    given = dict(zip(("start", "end"), asked or ends))
    unit = "km" if chart.geographic or to_user else "chart units"
    try:
        snapped = snap_ends(
            cost,
            ends[0],
            ends[1],
            land=land,
            neighbourhood=neighbourhood,
            max_km=np.inf,
            why=why or described,
        )
    except SnapError as exc:  # no usable pixel joins the other end
        said = "; ".join(_refusal(m, given[m.name], np.inf, snap, snap_km, show, unit) for m in exc.moves)
        raise SnapError(exc.moves, np.inf, unit, said) from None

    def km(m):  # a projected chart: great-circle km between the point asked for and the new one
        if to_user is None:
            return m.distance
        (a, b), (c, d) = given[m.name], show(m.to)
        return float(distance_km(a, b, c, d))

    far = [m for m in snapped.moves if not (snap and km(m) <= snap_km)]
    if far:
        said = "; ".join(_refusal(m, given[m.name], km(m), snap, snap_km, show, unit) for m in far)
        raise SnapError(far, snap_km if snap else 0.0, unit, said)
    notes = []
    for m in snapped.moves:
        notes.append(
            f"{m.name} {_pt(given[m.name])} is on an impassable pixel ({m.why}): moved "
            f"{km(m):.1f} {unit} to {_pt(show(m.to), 4)} (--snap, at most {snap_km:g} {unit})"
        )
        say(notes[-1])
    return list(snapped.ends), notes


def _pt(p, digits=None) -> str:
    return ",".join(f"{v:g}" if digits is None else f"{v:.{digits}f}" for v in p)


def _refusal(m, given, km, snap, snap_km, show, unit) -> str:
    here = f"{m.name} {_pt(given)} is on an impassable pixel ({m.why})"
    if m.to is None:
        return f"{here}; no pixel of the chart the ship may use is joined to the other end"
    there = f"the nearest point the ship may use is {_pt(show(m.to), 4)}, {km:.1f} {unit} away"
    if not snap:
        return f"{here}; {there}: give it, or pass --snap to move the {m.name} there"
    return (
        f"{here}; {there}, farther than --snap-km {snap_km:g}: give a point in water the ship "
        f"may use, or --snap-km {np.ceil(km):.0f} to move the {m.name} there"
    )
