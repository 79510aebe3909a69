"""The command line: ``seaway route CHART --from LAT,LON --to LAT,LON`` routes a ship across a
chart file; ``seaway demo`` through the built-in synthetic winter Kara Sea chart, from the Kara
Gate to the Vilkitsky Strait; ``seaway bench`` times the engine on the synthetic benchmark chart;
``seaway season DATE=CHART ... --from LAT,LON --to LAT,LON`` routes through dated ice charts;
``seaway route --forecast FILE`` routes through a weather forecast and ``seaway replan`` re-plans
a voyage from where the ship is through a newer one.
One module per command (`seaway route` keeps its options in routeargs.py, and those of weather
routing in forecastargs.py, beside the modules that run them); common.py holds what they share."""

from __future__ import annotations

import argparse
import os
import sys

from ..base.validate import one_line
from ..errors import NoRouteError
from .bench import add_bench_command, run_bench
from .common import EPILOG
from .demo import add_demo_command
from .demo import demo as run_demo
from .replan import add_replan_command, run_replan
from .route import run_route
from .routeargs import add_route_command
from .season import add_season_command, run_season


def build_parser() -> argparse.ArgumentParser:
    """The parser of the `seaway` command line (all its commands)."""
    parser = argparse.ArgumentParser(
        prog="seaway",
        description="Least-cost ship routes through sea ice, waves and weather on raster charts.",
        epilog=EPILOG + " 'seaway COMMAND --help' explains each command.",
    )
    commands = parser.add_subparsers(dest="command", required=True, metavar="command")
    add_demo_command(commands)
    add_route_command(commands)
    add_bench_command(commands)
    add_season_command(commands)
    add_replan_command(commands)
    return parser


def main(argv=None) -> int:
    args = build_parser().parse_args(argv)
    run = {
        "demo": run_demo,
        "route": run_route,
        "bench": run_bench,
        "season": run_season,
        "replan": run_replan,
    }[args.command]
    try:
        return run(args)
    except (NoRouteError, ValueError, OSError, ImportError) as exc:
        for note in getattr(exc, "notes", ()):  # what the voyage assumed or changed: said first
            print(f"seaway {args.command}: {note}", file=sys.stderr)
        print(f"seaway {args.command}: error: {exc}", file=sys.stderr)
        return 1
    except MemoryError as exc:  # a request the estimates (seaway.base.memory) let through
        print(
            f"seaway {args.command}: error: out of memory ({one_line(exc) or 'an allocation failed'}); "
            "give a coarser grid, a smaller box or fewer charts, or set SEAWAY_MEMORY_LIMIT lower",
            file=sys.stderr,
        )
        return 1
    except KeyboardInterrupt:
        print(f"seaway {args.command}: interrupted", file=sys.stderr)
        return 130


def entry(argv=None) -> None:
    """The program's entry point (``seaway`` and ``python -m seaway``): exit with main's status.

    An interrupted run leaves by ``os._exit(130)`` after flushing its output. ``sys.exit(130)``
    is not enough: under ``python -m``, CPython 3.11 remembers a KeyboardInterrupt that escaped
    any ``PyRun_String`` call while it arrived (Cython modules run one while they are imported)
    even when the program caught it later, and then ends the process by SIGINT (status -2)
    instead of 130. Exports are written atomically and cleaned up before main returns, so
    nothing is left for the interpreter's shutdown to do."""
    status = main(argv)
    if status == 130:
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except (OSError, ValueError):
                pass
        os._exit(130)
    sys.exit(status)
