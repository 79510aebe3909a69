"""The `seaway route` command: a route across a chart file, printed, written and plotted."""

from __future__ import annotations

import dataclasses

from ..base.units import KM_PER_NM
from ..depth import check_draft
from ..engine.api import route
from ..errors import NoRouteError
from ..ice.speed import ice_speed
from .chartfile import open_chart
from .common import Progress, searching, tell
from .constraints import constraint_options
from .depth import for_route
from .ends import check_ends
from .forecast import run_forecast_route
from .forecastargs import check_forecast_options
from .noroute import ice_chart, why_no_route
from .outputs import check_outputs, write_outputs
from .projected import end_pixel, pixel_latlon


def run_route(args) -> int:
    check_forecast_options(args)
    if args.forecast:  # weather routing (seaway.cli.forecast)
        return run_forecast_route(args)
    if args.chart is None:
        raise ValueError("give a CHART file, or --forecast FILE to route through a forecast on its own grid")
    say = Progress("route", args.quiet)
    planned = check_outputs(args.out, args.plot)  # before any work: nothing found is then lost
    say(f"reading {args.chart}")
    data = open_chart(
        args.chart,
        variable=args.variable,
        vessel=args.vessel,
        land_variable=args.land_variable,
        grid=args.grid,
        ends=(args.start, args.end),
        stage=args.assume_stage,
        fast_ice=args.fast_ice,
    )
    for note in data.notes:  # what the chart's reading assumed or decided: even with --quiet
        tell(note)
    cost = data.cost
    start, end = args.start, args.end
    if data.projection is not None:
        start, end = (
            end_pixel(cost, data.projection, p, name) for p, name in ((start, "start"), (end, "end"))
        )
    elif not ("lat" in cost.coords or "latitude" in cost.coords):
        say(
            "the chart has projected y/x coordinates but names no projection (CF grid_mapping): "
            "--from and --to are ROW,COL pixel indices"
        )
    chart_cost = cost
    cost, depth, shallow = for_route(
        args.depth,
        cost,
        draft=args.draft,
        ukc=args.ukc,
        variable=args.depth_variable,
        positive=args.depth_positive,
        say=say,
        crs=getattr(data.layers, "attrs", {}).get("crs"),
    )
    (start, end), moved = check_ends(
        cost,
        data.land,
        data.layers,
        (start, end),
        vessel=args.vessel,
        snap=args.snap,
        snap_km=args.snap_km,
        say=tell,
        neighbourhood=args.neighbourhood,
        reasons=shallow,
        chart_cost=chart_cost,
        to_user=pixel_latlon(cost, data.projection),
        asked=(args.start, args.end),
    )
    rows, cols = cost.shape
    say(
        f"routing on {rows} x {cols} pixels ({data.description}; {args.method}, "
        f"{args.neighbourhood}x{args.neighbourhood} stencil, edge cost {args.edge_cost})"
    )
    constraints = constraint_options(args)  # seaway.cli.constraints
    for name, value in constraints.items():
        if value not in (None, []):
            say(f"constraint {name}: {value if name != 'zones' else [z.name for z in value]}")
    try:
        # With a turn penalty the search settles (pixel, incoming step) states: scale the total.
        states = args.neighbourhood**2 - 1 if constraints["turn_penalty"] is not None else 1
        with searching(say, rows * cols * states):
            r = route(
                cost,
                start,
                end,
                land=data.land,
                neighbourhood=args.neighbourhood,
                edge_cost=args.edge_cost,
                method=args.method,
                **constraints,
            )
    except NoRouteError:
        used = any(v not in (None, []) for v in constraints.values())
        raise why_no_route(
            data, cost, (start, end), args, depth=depth, shallow=shallow, constrained=used
        ) from None
    say(f"found: cost {r.cost:.6g}, {len(r.pixels)} pixels, {r.stats.search.settled} settled")
    if constraints["via"] or constraints["turn_penalty"] is not None:
        say("not smoothed: smoothing would cut the via-points or ignore the turn penalty")
    elif not args.no_smooth:
        say(f"smoothing {r.course_changes} course changes")
        r = r.smoothed()
        done = r.stats.smoothing
        say(
            f"smoothed: cost {done.cost_before:.6g} -> {r.cost:.6g}, course changes "
            f"{done.course_changes_before} -> {done.course_changes_after}"
        )
    r = dataclasses.replace(
        r, name=args.name, speed_kn=args.speed, notes=r.notes + tuple(moved), requested=(args.start, args.end)
    )  # every output gives both ends
    if args.speed and ice_chart(data, args):  # times from the speed in the ice, never open water's
        knots = ice_speed(
            data.layers,
            args.vessel or "Arc7",
            args.speed,
            fast_ice=args.fast_ice,
            depth=depth if args.draft is not None else None,
            draft=args.draft,
        )
        r = r.with_ice_speed(knots)
        tell(f"times from the speed in the ice: {knots.attrs['model']}")
    if data.environment:
        r = r.with_environment(data.environment)
    if depth is not None:  # --depth, over a chart's own depth variable
        r = r.with_environment({"depth": depth})
    planar = r  # the PNG map draws the projected chart as it is
    if data.projection is not None:  # vertices in lat/lon for the legs and the outputs
        y, x = r.coords[:, 0], r.coords[:, 1]
        r = dataclasses.replace(r, latlon=data.projection.to_latlon(y, x))
    print(r)
    shoal = sum(check_draft(args.draft, args.ukc)) if args.draft is not None else None
    write_outputs(
        planned,
        r,
        planar=planar if data.projection is not None else None,
        title=_title(args, data, r),
        say=say,
        map_options={"shoal_m": shoal},
    )
    return 0


def _title(args, data, r) -> str:
    """The map's title: the route, its chart's date and class, its length and cost."""
    head = f"{args.name}" + (f", chart of {data.date}" if data.date else "")
    length = f"{r.length:.0f} km ({r.length / KM_PER_NM:.0f} nm)" if r.geographic else f"{r.length:.1f} units"
    return f"{head}: {length}, cost {r.cost:.5g} {r.unit}; {data.description}"
