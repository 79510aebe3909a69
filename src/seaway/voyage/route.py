"""A route across an opened chart (OpenChart.route), as ``seaway route CHART`` finds it: the ends
projected, checked and (with snap) moved to usable water, the draft enforced, the least-cost
search under the constraints, the no-route explanation, smoothing, the times in the ice and the
chart's variables along the legs; every assumption recorded in Route.notes."""

from __future__ import annotations

import contextlib
import dataclasses
from collections.abc import Callable, Collection
from typing import TYPE_CHECKING, Any

from ..base.interrupt import SettledProgress, reporting
from ..engine.api import route
from ..engine.snap import DEFAULT_SNAP_KM
from ..errors import NoRouteError
from ..ice.speed import ice_speed
from .depth import with_draft
from .ends import check_ends
from .noroute import why_no_route
from .projected import end_pixel, pixel_latlon

if TYPE_CHECKING:
    from ..constraints import KeepAway, Zone
    from ..result.route import Route
    from .chart import OpenChart

Say = Callable[[str], None]


def searching(progress: Say | None, pixels: int):
    """Within the block, a running search reports the pixels it has settled once a second."""
    return contextlib.nullcontext() if progress is None else reporting(SettledProgress(progress, pixels))


def route_chart(
    chart: OpenChart,
    start: tuple[float, float],
    end: tuple[float, float],
    *,
    vessel: str | None = None,
    speed_kn: float | None = None,
    snap_km: float | None = None,
    neighbourhood: int = 5,
    edge_cost: str = "max",
    method: str = "auto",
    smooth: bool = True,
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

    vessel: the ice class the chart's ice is priced for (default the chart's, else Arc7 on stage
        charts). speed_kn: the open-water speed; on an ice chart each leg's time comes from the
        class's speed in its ice (seaway.ice.speed), on other charts from this speed.
    snap_km: None (default): an end on an impassable pixel raises ValueError naming why and the
        nearest usable point; a distance: such an end moves there when it is at most that far
        (recorded in Route.notes and .requested).
    neighbourhood, edge_cost, method, via, turn_penalty, keep_away, zones: as seaway.route.
    smooth: any-angle smoothing (never costlier; not with via or turn_penalty).
    draft_m, ukc_m: the ship's draft and under-keel clearance (needs a chart opened with depth).
    progress: called with progress messages (stage, pixels settled), or None for silence.
    NoRouteError says why from the chart (its ice, land or depth)."""
    say = progress or (lambda message: None)
    cls = chart.ice_class(vessel)
    cost = chart.cost_for(vessel)
    asked = (tuple(start), tuple(end))
    if chart.projection is not None:
        start, end = (end_pixel(cost, chart.projection, p, n) for p, n in ((start, "start"), (end, "end")))
    elif not ("lat" in cost.coords or "latitude" in cost.coords):
        say(
            "the chart has projected y/x coordinates but names no projection (CF grid_mapping): "
            "--from and --to are ROW,COL pixel indices"
        )
    chart_cost = cost
    cost, shallow = with_draft(cost, chart.depth, draft_m, ukc_m, say)
    snap = snap_km is not None
    (start, end), moved = check_ends(
        cost,
        chart.land,
        chart.layers,
        (start, end),
        vessel=cls,
        snap=snap,
        snap_km=snap_km if snap else DEFAULT_SNAP_KM,
        say=lambda note: None,
        neighbourhood=neighbourhood,
        reasons=shallow,
        chart_cost=chart_cost,
        to_user=pixel_latlon(cost, chart.projection),
        asked=asked,
    )
    rows, cols = cost.shape
    say(
        f"routing on {rows} x {cols} pixels ({chart.description}"
        f"{f' for {cls}' if cls else ''}; {method}, {neighbourhood}x{neighbourhood} stencil, edge cost {edge_cost})"
    )
    constraints = dict(via=list(via), turn_penalty=turn_penalty, keep_away=keep_away, zones=zones)
    try:
        # With a turn penalty the search settles (pixel, incoming step) states: scale the total.
        states = neighbourhood**2 - 1 if turn_penalty is not None else 1
        with searching(progress, rows * cols * states):
            r = route(
                cost,
                start,
                end,
                land=chart.land,
                neighbourhood=neighbourhood,
                edge_cost=edge_cost,
                method=method,
                **constraints,
            )
    except NoRouteError:
        used = bool(via) or turn_penalty is not None or bool(keep_away) or bool(zones)
        err = why_no_route(
            chart,
            cost,
            (start, end),
            asked,
            vessel=cls,
            neighbourhood=neighbourhood,
            depth=chart.depth,
            draft=(draft_m, ukc_m) if shallow is not None else None,
            constrained=used,
        )
        err.notes = tuple(moved)
        raise err from None
    say(f"found: cost {r.cost:.6g}, {len(r.pixels)} pixels, {r.stats.search.settled} settled")
    if via or turn_penalty is not None:
        say("not smoothed: smoothing would cut the via-points or ignore the turn penalty")
    elif smooth:
        say(f"smoothing {r.course_changes} course changes")
        r = r.smoothed()
        done = r.stats.smoothing
        say(
            f"smoothed: cost {done.cost_before:.6g} -> {r.cost:.6g}, course changes "
            f"{done.course_changes_before} -> {done.course_changes_after}"
        )
    said = set(r.assumptions)
    notes = [n for n in chart.notes if n.removeprefix("assumed: ") not in said] + list(moved)
    r = dataclasses.replace(r, name=name, speed_kn=speed_kn, notes=r.notes + tuple(notes), requested=asked)
    if speed_kn and chart.is_ice and chart.layers is not None:  # times from the speed in the ice
        knots = ice_speed(
            chart.layers,
            cls,
            speed_kn,
            fast_ice=chart.options.fast_ice,
            depth=chart.depth if draft_m is not None else None,
            draft=draft_m,
        )
        r = r.with_ice_speed(knots)
        r = dataclasses.replace(
            r, notes=r.notes + (f"times from the speed in the ice: {knots.attrs['model']}",)
        )
    if chart.environment:
        r = r.with_environment(chart.environment)
    if chart.depth is not None:  # the chart's depth, or its own depth variable
        r = r.with_environment({"depth": chart.depth})
    if chart.projection is not None:  # vertices in lat/lon for the legs and the outputs
        y, x = r.coords[:, 0], r.coords[:, 1]
        r = dataclasses.replace(r, latlon=chart.projection.to_latlon(y, x))
    return r
