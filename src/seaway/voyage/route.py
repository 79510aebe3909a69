"""A route across an opened chart (OpenChart.route), as ``seaway route CHART`` finds it: the ends
projected, checked and (with snap_km) moved to usable water, the draft enforced, the search under
the constraints and the objective (least ice impact, Grinyak et al. 2022, or least time), the
no-route explanation, smoothing, the times in the ice for the ship (seaway.voyage.timing), the
schedule from a departure and the chart's variables along the legs; every assumption recorded
in Route.notes."""

from __future__ import annotations

import contextlib
import dataclasses
from collections.abc import Callable, Collection
from typing import TYPE_CHECKING, Any

import numpy as np

from ..base.interrupt import SettledProgress, reporting
from ..engine.api import prepare
from ..engine.snap import DEFAULT_SNAP_KM
from ..errors import NoRouteError, SeawayError
from ..models import EdgeCost
from .ends import check_ends
from .noroute import ClassProbe, why_no_route
from .pricing import price_chart
from .projected import end_pixel, pixel_latlon, true_cost, true_latlon
from .timing import blocked_words, chart_age, ice_time, search_cost

if TYPE_CHECKING:
    from ..constraints import KeepAway, Zone
    from ..result.route import Route
    from ..vessel import Vessel
    from .chart import OpenChart

Say = Callable[[str], None]
OBJECTIVES = ("impact", "time")


def searching(progress: Say | None, pixels: int):
    """Within the block, a running search reports the pixels it has settled once a second."""
    return contextlib.nullcontext() if progress is None else reporting(SettledProgress(progress, pixels))


def route_chart(
    chart: OpenChart,
    start: tuple[float, float],
    end: tuple[float, float],
    *,
    vessel: Vessel | str | None = None,
    speed_kn: float | None = None,
    depart: Any = None,
    objective: str = "impact",
    escort: bool = False,
    escort_speed_kn: float | None = None,
    stage_thickness: Any = None,
    compare: bool = True,
    snap_km: float | None = None,
    neighbourhood: int = 5,
    edge_cost: str = "max",
    method: str = "auto",
    smooth: bool = True,
    concentration_limit: bool = False,
    draft_m: float | None = None,
    ukc_m: float | None = None,
    via: Collection[tuple[float, float]] = (),
    turn_penalty: Any = None,
    keep_away: KeepAway | Collection[KeepAway] = (),
    zones: Zone | Collection[Zone] = (),
    name: str = "seaway route",
    progress: Say | None = None,
) -> Route:
    """The route from `start` to `end` on `chart`.

    vessel: a seaway.vessel.Vessel (a vessel file's: its class, service speed, draft, ice curve)
        or an ice class (a ship of that class at 12 kn, said); default the chart's class.
    speed_kn, draft_m, ukc_m: replace the vessel's open-water speed, draft and UKC.
    depart: the departure (a date numpy.datetime64 takes): every waypoint gets its ETA.
    objective: "impact" (least ice impact, Grinyak et al. 2022; edge_cost says how a step is
        priced) or "time" (the quickest route, exact: the line integral of hours per km).
    escort: where the ship has no speed of its own in ice its class may enter, go under
        icebreaker escort at escort_speed_kn (default 6 kn, an assumption) and mark those legs;
        without it such ice is avoided. stage_thickness: the thickness of a stage of development
        (seaway.ice.andreeva.stage_thickness: "mid" by default, "upper", "lower", {stage: m}).
    compare: on an ice chart with the impact objective, also find the quickest route and say
        how much quicker it is when it differs.
    snap_km: None (default): an end on an impassable pixel raises ValueError naming why and the
        nearest usable point; a distance: such an end moves there when it is at most that far.
    neighbourhood, method, via, turn_penalty, keep_away, zones: as seaway.route.
    smooth: any-angle smoothing (never costlier; not with via or turn_penalty).
    concentration_limit: close ice over the class's concentration limit (as a season does).
    progress: called with progress messages (stage, pixels settled), or None for silence.
    On an ice chart every leg has a time, a speed and (with depart) an ETA; NoRouteError says why
    from the chart (its ice, land or depth)."""
    say = progress or (lambda message: None)
    if objective not in OBJECTIVES:
        raise SeawayError(f"objective must be one of {', '.join(OBJECTIVES)} on a chart, got {objective!r}")
    pr = price_chart(
        chart,
        vessel=vessel,
        speed_kn=speed_kn,
        objective=objective,
        edge_cost=edge_cost,
        escort=escort,
        escort_speed_kn=escort_speed_kn,
        stage_thickness=stage_thickness,
        draft_m=draft_m,
        ukc_m=ukc_m,
        concentration_limit=concentration_limit,
        say=say,
    )
    ship, cls, draft, ukc, chart_cost = pr.ship, pr.cls, pr.draft, pr.ukc, pr.chart_cost
    cost, shallow, timing, routed, notes = pr.cost, pr.shallow, pr.timing, pr.routed, pr.notes
    asked = (tuple(start), tuple(end))
    if chart.projection is not None:
        start, end = (end_pixel(cost, chart.projection, p, n) for p, n in ((start, "start"), (end, "end")))
    elif not ("lat" in cost.coords or "latitude" in cost.coords):
        say(
            "the chart has projected y/x coordinates but names no projection (CF grid_mapping): "
            "--from and --to are ROW,COL pixel indices"
        )

    def price(c):  # the search's cost for another class: its ice, its speed (a ship of that class)
        if c == cls:
            return routed
        return price_chart(
            chart,
            vessel=c,
            speed_kn=ship.speed_kn if ship is not None else speed_kn,
            escort=escort,
            escort_speed_kn=escort_speed_kn,
            stage_thickness=stage_thickness,
            draft_m=draft,
            ukc_m=ukc,
            concentration_limit=concentration_limit,
        ).routed

    reasons = pr.reasons
    (start, end), moved = check_ends(
        routed,
        chart.land,
        chart.layers,
        (start, end),
        vessel=cls,
        snap=snap_km is not None,
        snap_km=snap_km if snap_km is not None else DEFAULT_SNAP_KM,
        say=lambda note: None,
        neighbourhood=neighbourhood,
        reasons=reasons,
        fast_ice=chart.options.fast_ice,
        chart_cost=chart_cost,
        to_user=pixel_latlon(cost, chart.projection),
        asked=asked,
    )
    rows, cols = cost.shape
    say(
        f"routing on {rows} x {cols} pixels ({chart.description}{f' for {cls}' if cls else ''}; "
        f"objective {objective}, {method}, {neighbourhood}x{neighbourhood} stencil)"
    )
    model = EdgeCost("integral", unit="h") if objective == "time" else EdgeCost(edge_cost)
    prepared = prepare(routed, land=chart.land, neighbourhood=neighbourhood, keep_away=keep_away, zones=zones)
    try:
        states = neighbourhood**2 - 1 if turn_penalty is not None else 1  # a turn search: (pixel, step)
        with searching(progress, rows * cols * states):
            r = prepared.route(
                start, end, model=model, method=method, via=list(via), turn_penalty=turn_penalty
            )
    except NoRouteError:
        used = bool(via) or turn_penalty is not None or bool(keep_away) or bool(zones)
        err = why_no_route(
            chart,
            routed,
            (start, end),
            asked,
            vessel=cls,
            neighbourhood=neighbourhood,
            depth=chart.depth,
            draft=(draft, ukc) if shallow is not None else None,
            constrained=used,
            blocked=blocked_words(shallow, timing),
            probe=ClassProbe(chart, price, neighbourhood) if timing is not None else None,
            escorted=(
                lambda: _escort_gets_through(
                    chart, cls, ship, cost, stage_thickness, draft, start, end, neighbourhood
                )
            )
            if timing is not None and not escort and timing.closed.any()
            else None,
        )
        err.notes = tuple(notes) + tuple(moved)
        raise err from None
    say(f"found: cost {r.cost:.6g}, {len(r.pixels)} pixels, {r.stats.search.settled} settled")
    if via or turn_penalty is not None:
        say("not smoothed: smoothing would cut the via-points or ignore the turn penalty")
    elif smooth:
        r = r.smoothed()
        done = r.stats.smoothing
        say(
            f"smoothed: cost {done.cost_before:.6g} -> {r.cost:.6g}, course changes {done.course_changes_before} -> {done.course_changes_after}"
        )
    said = set(r.assumptions)
    told = [n for n in chart.notes if n.removeprefix("assumed: ") not in said]
    departure = None if depart is None else np.datetime64(depart, "s")
    r = dataclasses.replace(
        r,
        name=name,
        speed_kn=ship.speed_kn if ship is not None else None,
        notes=r.notes + tuple(told) + tuple(notes) + tuple(moved),
        requested=asked,
        departure=departure,
    )
    r = true_latlon(r, chart.projection)  # projected: vertices in lat/lon, lengths in true km
    if timing is not None:
        r = r.with_ice_speed(timing.knots, escorted=timing.escorted if timing.escort_kn else None)
        hours = float(sum(leg.time_h for leg in r.legs()))
        extra = chart_age(chart.date, departure, hours)
        if objective == "impact" and compare and np.isfinite(hours):
            extra += _quickest(
                timing,
                routed,
                chart,
                start,
                end,
                hours,
                method,
                via,
                turn_penalty,
                neighbourhood,
                keep_away,
                zones,
            )
        r = dataclasses.replace(r, notes=r.notes + tuple(extra))
    if chart.environment:
        r = r.with_environment(chart.environment)
    if chart.depth is not None:  # the chart's depth, or its own depth variable
        r = r.with_environment({"depth": chart.depth})
    return r


def _quickest(
    timing, routed, chart, start, end, hours, method, via, turn_penalty, k, keep_away, zones
) -> list[str]:
    """The quickest route's time beside the route's, when it is quicker by more than 1 %."""
    hours_per_km = np.where(np.isfinite(np.asarray(routed.values, float)), timing.hours_per_km(), np.inf)
    fast = true_cost(chart.projection, routed.copy(data=hours_per_km))
    try:
        q = prepare(fast, land=chart.land, neighbourhood=k, keep_away=keep_away, zones=zones).route(
            start,
            end,
            model=EdgeCost("integral", unit="h"),
            method=method,
            via=list(via),
            turn_penalty=turn_penalty,
        )
    except NoRouteError:
        return []
    if q.cost >= hours * 0.99:
        return []
    q = true_latlon(q, chart.projection)
    return [
        f"the quickest route (objective time) takes {q.cost:.1f} h over {q.length:.0f} km, "
        f"{hours - q.cost:.1f} h less than this one ({hours:.1f} h, the least ice impact)"
    ]


def _escort_gets_through(chart, cls, ship, cost, stage_thickness, draft, start, end, k) -> bool:
    """Whether the voyage gets through with an icebreaker's escort (the default escort speed)."""
    t = ice_time(chart, cls, ship, cost, escort=True, stage_thickness=stage_thickness, draft_m=draft)
    try:
        prepare(search_cost(cost, t, "impact"), land=chart.land, neighbourhood=k).route(start, end)
    except NoRouteError:
        return False
    return True
