"""A season's ends and why no route gets through it: snap_season_ends, explain_season_no_route.

**Ends.** In a season the ship may wait: an end in ice closed at departure but open in a later
chart is usable (the route waits there). Only an end that no chart from the departure on lets
the class use (land, off every chart, or ice closed for the class in every chart) is moved, by
seaway.engine.snap.snap_ends: to the nearest pixel some chart opens, in water that joins both
ends (pixels some chart opens, joined by the engine's stencil; whether the ice opens them in
time is the route's question), at most `max_km` away.

**No route.** With waiting allowed and the last chart holding for ever, no route means that no
sequence of the charts lets the class through. The explanation reads the season's most open
chart for the class (the one from the departure on with the most pixels the class may use; the
later one on a tie): every pixel the class may not use there gets a level, 1 + the place in
seaway.icenav.noroute.LADDER of the weakest class the season's own speed model lets in (the top
level when none), and the least-barrier way between the ends (seaway.engine.reach) names the ice
on it the class may not enter (stage, concentration or thickness; km). The weakest class of the
ladder that gets through the season is found by routing the season for the classes around the
one that way needs (one search each). How far the ship gets is read from its arrival field
through the season. Only when no way joins the ends with all ice open does the message say to
check the land mask. Ice is named as seaway.icenav.noroute names it on one chart, fast ice included
("fast ice of unknown stage, assumed thin first-year ice (SA 87)", "..., closed by the fast_ice
rule"): the model's fast-ice rule (IceSeasonTime.fast_ice) decides, chart by chart."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from ..base.sphere import distance_km
from ..engine.api import prepare
from ..engine.reach import Reach, chart_order, least_barrier, with_reach
from ..engine.snap import DEFAULT_SNAP_KM, SnappedEnds, snap_ends
from ..errors import NoRouteError
from ..ice.classes import get_class
from ..ice.seasonfast import describer
from ..ice.seasonspeed import frame_speed_kn
from ..models import IceSeasonTime
from ..result.environment import weighted_samples
from .noroute import LADDER, NO_CLASS, SHOWN

if TYPE_CHECKING:
    from ..ice.seasongrid import SeasonGrid

__all__ = ["usable", "closed_reason", "snap_season_ends", "explain_season_no_route"]


def usable(model: IceSeasonTime) -> np.ndarray:
    """Pixels some chart of the season, from the departure on, lets the model's class use."""
    return model.open_somewhen & ~model.season.dry


def closed_reason(model: IceSeasonTime):
    """(row, col) -> what keeps the class off a pixel in every chart from the departure on."""
    grid, first = model.season, model.season.times.size - model.valid_from_h.size
    read: list = []  # the departure chart's describer, read when a pixel is first asked about

    def ice(r, c) -> str:
        if not read:
            read.append(describer(grid.ds.isel(time=first), model.fast_ice))
        return read[0](r, c)

    def why(r, c) -> str:
        if grid.dry[r, c]:
            if "off_chart" in grid.ds and bool(grid.ds["off_chart"].values[:, r, c].all()):
                return "off every chart of the season: its ice is unknown"
            return "land"
        return (
            f"ice {_who(model)} may not enter in any chart from {model.departure} on; "
            f"at departure {ice(r, c)}"
        )

    return why


def _who(model) -> str:
    return f"{'an' if model.ice_class[0] in 'AaIi' else 'a'} {model.ice_class} ship"


def snap_season_ends(
    model: IceSeasonTime, start, end, *, neighbourhood: int = 5, max_km: float = DEFAULT_SNAP_KM
) -> SnappedEnds:
    """The ends of a route through the season of `model` (an IceSeasonTime): an end no chart from
    the departure on lets the class use moves to the nearest pixel one does, in water that joins
    both ends, at most max_km away (else seaway.engine.snap.SnapError, naming the distance;
    max_km=0: report, never move). An end closed at departure but open later stays (the route
    waits). `.record(route)` puts the requested ends and the moves on the route."""
    grid = model.season
    cost = grid.template.copy(data=np.where(usable(model), 1.0, np.inf))
    return snap_ends(
        cost, start, end, land=grid.dry, neighbourhood=neighbourhood, max_km=max_km, why=closed_reason(model)
    )


def _frame_open(grid, k, ice_class, v0_kn, speed, speed_options) -> np.ndarray:
    """Where chart k lets `ice_class` go (the season's speed model)."""
    v = frame_speed_kn(grid.ds.isel(time=k), ice_class, v0_kn, speed, **speed_options)
    return (np.asarray(v, float) > 0) & ~grid.dry


def _passes(grid, ice_class, model, prepared, start, end, speed, speed_options) -> bool:
    """Does `ice_class` get through the season (one search)?"""
    try:
        other = IceSeasonTime(
            grid, ice_class, model.v0_kn, departure=model.departure, speed=speed, **speed_options
        )
        prepared.route(start, end, model=other, method="astar")
        return True
    except (NoRouteError, ValueError):  # includes an end closed all season, a class that goes nowhere
        return False


def explain_season_no_route(
    grid: SeasonGrid,
    model: IceSeasonTime,
    start,
    end,
    *,
    neighbourhood: int = 5,
    speed: Any = "andreeva",
    asked=None,
    **speed_options: Any,
) -> NoRouteError:
    """The NoRouteError saying why `model` (an IceSeasonTime on `grid`) finds no route from
    `start` to `end` (see the module): cause, closing_ice, weakest_class, reachable and
    reachable_km as in seaway.errors.NoRouteError. speed and speed_options: as the model was
    built with (the other classes are routed with them, and with the model's fast-ice rule);
    asked: the ends as the user gave them. Fast ice is named as seaway.icenav.noroute names it."""
    speed_options = {**speed_options, "fast_ice": model.fast_ice}
    prepared = prepare(grid, neighbourhood=neighbourhood)
    chart = prepared.chart
    first = grid.times.size - model.valid_from_h.size
    opened = np.isfinite(model.hours_per_km) & ~grid.dry
    i = int(opened.shape[0] - 1 - np.argmax(opened.sum(axis=(1, 2))[::-1]))  # the later on a tie
    k = first + i
    levels = np.where(opened[i], 0.0, float(NO_CLASS))
    for n in range(len(LADDER) - 1, -1, -1):  # strongest first: the weakest that opens stays
        try:
            here = _frame_open(grid, k, LADDER[n], model.v0_kn, speed, speed_options)
        except ValueError:  # a class that passes no ice (h_pass 0)
            continue
        levels[here & ~opened[i]] = n + 1
    levels[grid.dry] = -1.0
    way = least_barrier(chart, levels, start, end, neighbourhood)
    a, b = asked or (start, end)
    dates = f"{str(grid.times[first])[:16]} to {str(grid.times[-1])[:16]}"
    head = (
        f"no route for {_who(model)} from {_pt(a)} to {_pt(b)} through the season "
        f"(charts of {dates}, waiting allowed): "
    )
    if way is None:
        err = NoRouteError(
            head + "the ends lie in separate water bodies even with all ice open (or a "
            f"passage is narrower than the land rule allows with neighbourhood={neighbourhood}): "
            "check the land mask, try a larger neighbourhood or choose other ends",
            cause="land",
        )
        return with_reach(err, _reach(prepared, model, start, end))
    closing = _closing(describer(grid.ds.isel(time=k), model.fast_ice), grid.ds.isel(time=k), levels, way)
    px = weighted_samples(way)[0]
    top = int(levels[px[:, 0], px[:, 1] % chart.shape[1]].max())
    weakest = _weakest(grid, model, prepared, start, end, top, speed, speed_options)
    share = 100.0 * opened[i].sum() / max(int((~grid.dry).sum()), 1)
    said = "; ".join(f"{name}: {km:.0f} km" for name, km in closing[:SHOWN])
    more = f" and {len(closing) - SHOWN} more kinds" if len(closing) > SHOWN else ""
    through = (
        f"the weakest class that gets through the season is {weakest}"
        if weakest
        else f"no class up to {LADDER[-1]} gets through the season"
    )
    err = NoRouteError(
        f"{head}ice closes the way in the season's most open chart for {model.ice_class}, that of "
        f"{str(grid.times[k])[:16]} ({share:.0f} % of the sea open to it): {said}{more}; {through}",
        cause="ice",
        closing_ice=closing,
        weakest_class=weakest,
    )
    return with_reach(err, _reach(prepared, model, start, end))


def _closing(ice, ds, levels, way) -> list:
    """[(the ice at its concentrations (who may enter), km)] the way crosses closed, most first;
    ice: seaway.ice.seasonfast.describer of the chart `ds`."""
    px, km, _ = weighted_samples(way)
    r, c = px[:, 0], px[:, 1] % levels.shape[1]
    found: dict = {}
    ct = np.round(np.asarray(ds["CT"].values, float), 1)
    for j in np.flatnonzero(levels[r, c] > 0):
        level = int(levels[r[j], c[j]])
        who = "no class may enter" if level >= NO_CLASS else f"{LADDER[level - 1]} and stronger may enter"
        name = ice(r[j], c[j], concentration=False)
        entry = found.setdefault((name, who), [0.0, []])
        entry[0] += float(km[j])
        if np.isfinite(ct[r[j], c[j]]):
            entry[1].append(float(ct[r[j], c[j]]))
    out = []
    for (name, who), (dist, cts) in found.items():
        if cts:
            lo, hi = min(cts), max(cts)
            name += f" at {hi:g}/10" if lo == hi else f" at {lo:g}-{hi:g}/10"
        out.append((f"{name} ({who})", dist))
    return sorted(out, key=lambda kv: -kv[1])


def _weakest(grid, model, prepared, start, end, top, speed, speed_options):
    """The weakest class of LADDER that gets through the season, or None: from the class the
    least-barrier way needs, up until one passes, then down while a weaker one passes (a
    stronger Register class opens everything a weaker one does)."""
    if top >= NO_CLASS:
        return None
    own = LADDER.index(model.ice_class) if model.ice_class in LADDER else -1
    n = max(top - 1, own + 1)
    while n < len(LADDER) and not _passes(grid, LADDER[n], model, prepared, start, end, speed, speed_options):
        n += 1
    if n == len(LADDER):
        return None
    while n - 1 > own and _passes(grid, LADDER[n - 1], model, prepared, start, end, speed, speed_options):
        n -= 1
    return get_class(LADDER[n]).name


def _reach(prepared, model, start, end) -> Reach | None:
    """The pixel the ship reaches through the season that is nearest the end."""
    try:
        field = chart_order(prepared.cost_field(start, model=model), prepared.chart)
    except ValueError:
        return None
    chart = prepared.chart
    cand = np.argwhere(np.isfinite(field))
    points = chart.pixel_coords(cand)
    if chart.geographic:
        d = distance_km(points[:, 0], points[:, 1], float(end[0]), float(end[1]))
    else:
        there = chart.pixel_coords(np.array([[int(end[0]), int(end[1])]]))[0]
        d = np.hypot(points[:, 0] - there[0], points[:, 1] - there[1])
    j = int(np.argmin(d))
    p = (float(points[j, 0]), float(points[j, 1]))
    if chart.geographic:
        p = (p[0], (p[1] + 180.0) % 360.0 - 180.0)
    return Reach((int(cand[j, 0]), int(cand[j, 1])), p, float(d[j]))


def _pt(p) -> str:
    return ",".join(f"{float(v):g}" for v in p)
