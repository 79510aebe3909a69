"""Why a class cannot get through an ice chart: explain_no_route.

It answers what a navigator asks when no route is found, from the chart and the engine's own
searches (seaway.engine.reach):

* **what closes the way**: every pixel the ship may not enter gets a level, 1 + the place in
  LADDER of the weakest class that may enter its ice (Grinyak et al. 2022's tables, by the
  governing stage; seaway.ice.impact), or the top level when no class may (unknown ice, glacier
  ice, fast ice closed by the fast_ice rule, no chart polygon) or when something else closes it
  (`blocked_name`: e.g. too shallow for the draft). The least-barrier way between the ends
  (seaway.engine.reach.least_barrier) crosses as little of the top level as it can, then of the
  next...; the ice on it that the ship may not enter, by stage, concentration and form ("fast
  ice", "first-year ice (SA 86) at 10/10"), with its km, is what closes the way;
* **the weakest class that gets through**: the highest level on that way, checked by routing
  that class (None when no class of LADDER gets through);
* **how far the ship gets**: the pixel its own cost field from the start reaches that is
  nearest the end, and its distance;
* and only when no way joins the ends even with every ice opened, the land (or the stencil)
  keeps them apart: then, and only then, the message says to check the land mask.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from ..engine.api import route
from ..engine.prepared import PreparedChart
from ..engine.reach import chart_order, least_barrier, nearest_reachable, with_reach
from ..errors import NoRouteError
from ..ice.classes import get_class, with_article
from ..ice.forms import DEFAULT_FAST_ICE, fast_ice_mask, fast_ice_stage, ice_words
from ..ice.impact import chart_impact, governing_stage, ice_impact, table_for
from ..models.base import EdgeCost
from ..result.environment import weighted_samples

#: The classes asked, weakest first (Russian Register; IACS and FSICR classes use these tables).
LADDER = ("none", "Ice1", "Ice2", "Ice3", "Arc4", "Arc5", "Arc6", "Arc7", "Arc8", "Arc9")
NO_CLASS = len(LADDER) + 1  # the level of what no class may enter
SHOWN = 4  # kinds of ice named in the message


def explain_no_route(
    ds,
    ice_class,
    start,
    end,
    *,
    cost=None,
    neighbourhood=5,
    fast_ice=DEFAULT_FAST_ICE,
    blocked_name="closed by the cost, not by the ice",
    show=None,
    asked=None,
    passable=None,
    gets_through=None,
) -> NoRouteError:
    """The NoRouteError saying why an `ice_class` ship gets no route from `start` to `end` on
    the ice chart `ds` (a SIGRID-style Dataset: CT, SA, ..., land; or one with a
    stage_of_development), with the attributes of seaway.errors.NoRouteError: cause,
    closing_ice, weakest_class, reachable, reachable_km. See the module for how.

    cost: the cost the route was searched on (default chart_impact(ds, ice_class, fast_ice=...));
        its impassable pixels whose ice the class may enter are closed by something else,
        named `blocked_name` (e.g. "water shallower than draft + UKC").
    show: (row, col) -> the point to report (a projected chart's lat/lon); asked: the ends as
    the user gave them, for the message (default start, end).
    passable: class name -> bool mask (on the chart's grid) of the pixels that class may cross
        under the voyage's whole model (its ice table and, e.g., its speed in the ice); default
        its ice table (Grinyak et al. 2022). gets_through: class name -> whether that class finds
        a route between the ends under the same model; the weakest class named is the first of
        LADDER from the way's top level that does (default: the class's ice table, checked
        along the least-barrier way and by routing)."""
    cls = get_class(ice_class).name
    stage = _stage(ds, fast_ice)
    if cost is None:
        cost = (
            chart_impact(ds, cls, fast_ice=fast_ice) if "SA" in ds else ice_impact(stage, cls, unknown=np.inf)
        )
    land = ds["land"] if "land" in ds else None
    prepared = PreparedChart(cost, land=land, neighbourhood=neighbourhood)
    chart = prepared.chart
    kinds = _Kinds(ds, chart, stage, fast_ice, blocked_name, cls, passable)
    way = least_barrier(chart, kinds.levels, start, end, neighbourhood)
    reach = nearest_reachable(prepared, start, end)
    unit = "km" if chart.geographic or show else "chart units"
    who = f"{with_article(cls)} ship"
    a, b = asked or (start, end)
    head = f"no route for {who} from {_pt(a)} to {_pt(b)}: "
    if way is None:
        err = NoRouteError(
            head + "the ends lie in separate water bodies even with all ice open "
            f"(or a passage is narrower than the land rule allows with neighbourhood="
            f"{neighbourhood}): check the land mask, try a larger neighbourhood or "
            "choose other ends",
            cause="land",
        )
        return with_reach(err, reach, show, unit, asked[1] if asked else None)
    px, km, _ = weighted_samples(way)  # the pixels it crosses, every half pixel, and their km
    closing = kinds.on(px, km)
    if gets_through is not None:
        weakest = next(
            (c for c in LADDER[max(kinds.top(px), 1) - 1 :] if kinds.top(px) < NO_CLASS and gets_through(c)),
            None,
        )
        if weakest is None:  # the way's top level is not the whole story: ask every stronger class
            weakest = next(
                (c for c in LADDER[LADDER.index(cls) + 1 :] if cls in LADDER and gets_through(c)), None
            )
    else:
        weakest = _weakest(kinds, way, px, chart, start, end, neighbourhood)
    said = "; ".join(f"{name}: {km:.0f} km" for name, km in closing[:SHOWN])
    more = f" and {len(closing) - SHOWN} more kinds" if len(closing) > SHOWN else ""
    through = (
        f"the weakest class that gets through is {weakest}"
        if weakest
        else f"no class of seaway.ice.classes (up to {LADDER[-1]} and the icebreakers) gets through"
    )
    ice = any(kinds.is_ice(name) for name, _ in closing)
    err = NoRouteError(
        f"{head}{'ice' if ice else 'what'} closes the way: {said}{more}; {through}",
        cause="ice" if ice else "impassable",
        closing_ice=closing,
        weakest_class=weakest,
    )
    return with_reach(err, reach, show, unit, asked[1] if asked else None)


def _stage(ds, fast_ice):
    if "SA" in ds and "CT" in ds:
        return governing_stage(ds, fast_ice=fast_ice)
    st = ds["stage_of_development"]
    return st.isel({d: 0 for d in st.dims[:-2]}) if st.ndim > 2 else st


class _Kinds:
    """The level and the kind of ice of every pixel the ship may not enter."""

    def __init__(self, ds, chart, stage, fast_ice, blocked_name, cls, passable=None):
        self.chart, self.blocked_name = chart, blocked_name
        self.stage = chart_order(stage, chart)
        land = chart.land != 0 if chart.land is not None else np.zeros(chart.shape, bool)
        closed = ~(np.isfinite(chart.values) & (chart.values >= 0)) & ~land
        own = table_for(cls)
        self.other = np.zeros(chart.shape, bool)  # closed though the class may enter the ice
        levels = np.where(closed, float(NO_CLASS), 0.0)
        if passable is not None:  # the voyage's whole model, class by class, weakest first
            left = closed.copy()
            for k, c in enumerate(LADDER):
                opens = left & (chart_order(passable(c), chart) != 0)
                levels[opens], left = k + 1.0, left & ~opens
            if cls in LADDER:  # closed for the class though its own model opens it: something else
                self.other = closed & (chart_order(passable(cls), chart) != 0)
        else:
            for code in np.unique(self.stage[closed & np.isfinite(self.stage)]):
                here = closed & (self.stage == code)
                if np.isfinite(own.get(float(code), np.inf)):
                    self.other |= here
                    continue
                first = next(
                    (k for k, c in enumerate(LADDER) if np.isfinite(table_for(c).get(float(code), np.inf))),
                    None,
                )
                levels[here] = NO_CLASS if first is None else first + 1
        levels[self.other] = NO_CLASS
        self.levels = np.where(land, -1.0, levels)
        layer = lambda name: chart_order(ds[name], chart) if name in ds else None
        self.off = layer("off_chart")
        self.ct = layer("CT") if "CT" in ds else layer("sea_ice_concentration")
        self.fast = chart_order(fast_ice_mask(ds), chart) != 0 if "CT" in ds else None
        self.assumed = chart_order(fast_ice_stage(ds, fast_ice)[2], chart) != 0 if "SA" in ds else None
        self.label = "SA" if "SA" in ds else "WMO"
        self.guessed = "assumed" in str(ds["SA"].attrs.get("long_name", "")) if "SA" in ds else False

    def kind(self, r, c) -> str:
        """What closes pixel (r, c): its ice (stage, form), or blocked_name."""
        if self.other[r, c]:
            return self.blocked_name
        if self.off is not None and self.off[r, c]:
            return "no chart polygon (unknown ice)"
        fast = self.fast is not None and bool(self.fast[r, c])
        assumed = self.assumed is not None and bool(self.assumed[r, c])
        return ice_words(self.stage[r, c], fast, assumed, self.label, self.guessed)

    def who(self, r, c) -> str:
        level = self.levels[r, c]
        if self.other[r, c]:
            return ""
        return (
            "no class may enter" if level >= NO_CLASS else f"{LADDER[int(level) - 1]} and stronger may enter"
        )

    def is_ice(self, name: str) -> bool:
        return not name.startswith(self.blocked_name)

    def on(self, px, km) -> list:
        """[(kind at its concentrations (who may enter), km)] of the closed pixels among the
        samples `px` of a way (each standing for `km`), most km first."""
        r, c = px[:, 0], px[:, 1] % self.chart.shape[1]
        found: dict = {}
        for i in np.flatnonzero(self.levels[r, c] > 0):
            key = (self.kind(r[i], c[i]), self.who(r[i], c[i]))
            entry = found.setdefault(key, [0.0, []])
            entry[0] += float(km[i])
            if self.ct is not None and np.isfinite(self.ct[r[i], c[i]]):
                entry[1].append(float(self.ct[r[i], c[i]]))
        out = []
        for (kind, who), (dist, cts) in found.items():
            if cts:
                lo, hi = min(cts), max(cts)
                kind += f" at {hi:g}/10" if lo == hi else f" at {lo:g}-{hi:g}/10"
            out.append((kind + (f" ({who})" if who else ""), dist))
        return sorted(out, key=lambda kv: -kv[1])

    def top(self, px) -> int:
        return int(self.levels[px[:, 0], px[:, 1] % self.chart.shape[1]].max())


def _weakest(kinds, way, px, chart, start, end, neighbourhood):
    """The weakest class of LADDER that gets through, or None: the top level on the least-barrier
    way, checked step by step on that class's chart (the engine's closed-segment rule), else by
    routing it and the stronger classes."""
    level = kinds.top(px)
    if level >= NO_CLASS:
        return None
    for k in range(max(level, 1) - 1, len(LADDER)):
        u = ice_impact(kinds.stage, LADDER[k], unknown=np.inf)
        u[kinds.other | ~np.isfinite(kinds.stage)] = np.inf
        own = dataclasses.replace(chart, values=np.ascontiguousarray(u, dtype=float))
        seg = EdgeCost("max").segments(own, neighbourhood)
        v = way.vertices
        if all(np.isfinite(seg.leg(a, b)[0]) for a, b in zip(v[:-1], v[1:])):
            return LADDER[k]
        where = (
            {"lat": chart.lat, "lon": chart.lon}
            if chart.geographic
            else {"dx": chart.grid.dx, "dy": chart.grid.dy}
        )
        try:
            route(u, start, end, land=chart.land, neighbourhood=neighbourhood, **where)
            return LADDER[k]
        except NoRouteError:
            continue
    return None


def _pt(p) -> str:
    return ",".join(f"{float(v):g}" for v in p)


__all__ = ["LADDER", "explain_no_route"]
