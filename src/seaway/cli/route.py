"""The `seaway route` command: a route across a chart file (seaway.open_chart, OpenChart.route),
printed, written and plotted."""

from __future__ import annotations

import dataclasses
import os

from ..base.units import KM_PER_NM
from ..depth import check_draft
from ..errors import SeawayError
from ..output.files import check_outputs, write_outputs
from ..voyage import ChartOptions, open_chart
from .common import Progress, tell, vessel_from
from .constraints import constraint_options
from .forecast import run_forecast_route
from .forecastargs import check_forecast_options


def chart_options(args) -> ChartOptions:
    """The chart's options from the command line (seaway.voyage.ChartOptions)."""
    return ChartOptions(
        variable=args.variable,
        land_variable=args.land_variable,
        grid=args.grid,
        fast_ice=args.fast_ice,
        assume_stage=args.assume_stage,
        depth=getattr(args, "depth", None),
        depth_variable=getattr(args, "depth_variable", None),
        depth_positive=getattr(args, "depth_positive", None),
        land=getattr(args, "land", None),
    )


def run_route(args) -> int:
    check_forecast_options(args)
    if args.forecast:  # weather routing (seaway.cli.forecast)
        return run_forecast_route(args)
    if args.chart is None:
        raise SeawayError("give a CHART file, or --forecast FILE to route through a forecast on its own grid")
    say = Progress("route", args.quiet)
    planned = check_outputs(args.out, args.plot)  # before any work: nothing found is then lost
    say(f"reading {args.chart}")
    vessel = vessel_from(args) if args.vessel_file else args.vessel
    chart = open_chart(
        args.chart, vessel=vessel_class(args), ends=(args.start, args.end), options=chart_options(args)
    )
    for note in chart.notes:  # what the chart's reading assumed or decided: even with --quiet
        tell(note)
    constraints = constraint_options(args)  # seaway.cli.constraints
    for name, value in constraints.items():
        if value not in (None, []):
            say(f"constraint {name}: {value if name != 'zones' else [z.name for z in value]}")
    r = chart.route(
        args.start,
        args.end,
        vessel=vessel,
        speed_kn=args.speed,
        depart=args.depart,
        objective=args.objective or "impact",
        escort=args.escort,
        escort_speed_kn=args.escort_speed,
        stage_thickness=args.stage_thickness,
        concentration_limit=args.concentration_limit,
        snap_km=args.snap_km if args.snap else None,
        neighbourhood=args.neighbourhood,
        edge_cost=args.edge_cost,
        method=args.method,
        smooth=not args.no_smooth,
        draft_m=args.draft,
        ukc_m=args.ukc,
        name=args.name,
        progress=None if args.quiet else say,
        **constraints,
    )
    for note in r.notes:  # what the route added: moved ends, the time model
        if note not in chart.notes:
            tell(note)
    print(r)
    shoal = sum(check_draft(args.draft, args.ukc)) if args.draft is not None else None
    write_outputs(
        planned,
        r,
        planar=dataclasses.replace(r, latlon=None) if chart.projection is not None else None,
        title=_title(args, chart, r),
        say=say,
        map_options={"shoal_m": shoal},
    )
    return 0


def vessel_class(args):
    """The ice class of --vessel, else of --vessel-file, else None."""
    if args.vessel or not args.vessel_file:
        return args.vessel
    return vessel_from(args).ice_class


def _title(args, chart, r) -> str:
    """The map's title: the route, its chart's date and class, its length and cost."""
    head = f"{args.name}" + (f", chart of {chart.date}" if chart.date else "")
    length = f"{r.length:.0f} km ({r.length / KM_PER_NM:.0f} nm)" if r.geographic else f"{r.length:.1f} units"
    cls = chart.ice_class(vessel_class(args))
    what = chart.description
    source = os.fspath(chart.source)
    if os.path.basename(source) != source:  # the chart file's name, not its full path
        what = what.replace(source, os.path.basename(source))
    return f"{head}: {length}, cost {r.cost:.5g} {r.unit}; {what}" + (f", {cls}" if cls else "")
