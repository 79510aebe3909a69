"""What the commands share: argument types, the exit-status epilog, progress on stderr."""

from __future__ import annotations

import argparse
import contextlib
import dataclasses
import sys
import time

import numpy as np

from ..base.interrupt import SettledProgress, reporting
from ..engine.snap import DEFAULT_SNAP_KM
from ..ice.forms import check_fast_ice
from ..vessel import load
from ..voyage.ship import as_vessel

#: The exact methods a command may be asked for.
CLI_METHODS = ("auto", "bidirectional", "astar", "dijkstra")
EPILOG = (
    "exit status: 0 done; 1 no route, or a chart or output file that cannot be used; "
    "2 a bad command line. Progress goes to stderr, results to stdout."
)


def point(text: str) -> tuple[float, float]:
    """argparse type for LAT,LON."""
    try:
        a, b = (float(v) for v in text.replace(" ", "").split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"expected LAT,LON in decimal degrees (e.g. 70.3,58.5; write --from=-33.9,18.4 for a "
            f"negative first number), got {text!r}"
        ) from None
    if not (np.isfinite(a) and np.isfinite(b)):
        raise argparse.ArgumentTypeError(f"LAT,LON must be finite numbers, got {text!r}")
    return a, b


def add_ends(parser: argparse.ArgumentParser) -> None:
    """--from and --to: the ends of a route."""
    parser.add_argument(
        "--from",
        dest="start",
        type=point,
        required=True,
        metavar="LAT,LON",
        help="start in decimal degrees (ROW,COL on charts with projected y/x)",
    )
    parser.add_argument(
        "--to",
        dest="end",
        type=point,
        required=True,
        metavar="LAT,LON",
        help="end in decimal degrees (ROW,COL on charts with projected y/x)",
    )


def add_snap_options(parser: argparse.ArgumentParser, where: str) -> None:
    """--snap and --snap-km: move an end the ship may not use (`where`: what such an end is)."""
    parser.add_argument(
        "--snap",
        action="store_true",
        help=f"move a start or end {where} to the nearest point the ship may use in water "
        "that joins both ends, at most --snap-km away; the ends asked for and used are "
        "in every output (default: stop with an error naming why, that point and its "
        "distance)",
    )
    parser.add_argument(
        "--snap-km",
        type=positive_km,
        default=DEFAULT_SNAP_KM,
        metavar="KM",
        help=f"the farthest --snap moves an end (default {DEFAULT_SNAP_KM:g} km; farther: "
        "stop, naming the distance; 0: never move)",
    )


def positive_km(text: str) -> float:
    """argparse type for a distance in km (>= 0)."""
    try:
        km = float(text)
    except ValueError:
        km = float("nan")
    if not (np.isfinite(km) and km >= 0):
        raise argparse.ArgumentTypeError(f"expected a distance in km (>= 0), got {text!r}")
    return km


def grid(text: str) -> tuple:
    """argparse type for SOUTH,NORTH,WEST,EAST,RES (degrees)."""
    try:
        south, north, west, east, res = (float(v) for v in text.replace(" ", "").split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"expected SOUTH,NORTH,WEST,EAST,RES in degrees (e.g. 58,64,-55,-37,0.02), got {text!r}"
        ) from None
    if not (south < north and west < east and res > 0):
        raise argparse.ArgumentTypeError(f"need SOUTH < NORTH, WEST < EAST and RES > 0, got {text!r}")
    return south, north, west, east, res


def size(text: str) -> tuple[int, int]:
    try:
        r, c = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected ROWSxCOLS, e.g. 950x1150, got {text!r}") from None
    if r < 20 or c < 20:
        raise argparse.ArgumentTypeError(f"the chart must be at least 20x20, got {text!r}")
    return r, c


class Progress:
    """Stage messages with their time on stderr (silent with --quiet)."""

    def __init__(self, command: str, quiet: bool):
        self.command, self.quiet, self.t0 = command, quiet, time.perf_counter()

    def __call__(self, message: str) -> None:
        if not self.quiet:
            print(
                f"seaway {self.command}: [{time.perf_counter() - self.t0:6.1f} s] {message}",
                file=sys.stderr,
                flush=True,
            )


def searching(say, pixels: int):
    """Within the block, a running search reports the pixels it has settled once a second."""
    return contextlib.nullcontext() if say.quiet else reporting(SettledProgress(say, pixels))


def tell(message: str, command: str = "route") -> None:
    """What changed the voyage or was assumed (a snapped end): on stderr even with --quiet."""
    print(f"seaway {command}: {message}", file=sys.stderr, flush=True)


def neighbourhood(text: str) -> int:
    """argparse type for the k of the k x k stencil."""
    try:
        k = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be an odd integer from 3 to 15, got {text!r}") from None
    if k < 3 or k > 15 or k % 2 == 0:
        raise argparse.ArgumentTypeError(f"must be an odd integer from 3 to 15, got {k}")
    return k


def fast_ice(text: str):
    """argparse type of --fast-ice: 'nearby', 'closed' or a WMO stage code (seaway.ice.forms)."""
    try:
        return check_fast_ice(text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def depart_window(text: str) -> tuple:
    """argparse type for FIRST,LAST[,HOURS] (ISO times; hours between departures, default 24)."""
    parts = text.replace(" ", "").split(",")
    try:
        first, last = (np.datetime64(p.rstrip("Z"), "s") for p in parts[:2])
        step = float(parts[2]) if len(parts) > 2 else 24.0
    except (ValueError, IndexError):
        raise argparse.ArgumentTypeError(
            f"expected FIRST,LAST[,HOURS], e.g. 2026-07-01,2026-07-10,12, got {text!r}"
        ) from None
    if len(parts) > 3 or last < first or not step > 0:
        raise argparse.ArgumentTypeError(f"need FIRST <= LAST and HOURS > 0, got {text!r}")
    return first, last, step


def vessel_from(args):
    """The Vessel of the command line: --vessel-file (its values), --vessel CLASS (its class, or
    a ship of that class), --speed, --displacement, --draft and --ukc (replacing the file's);
    None when none is given."""
    ship = load(args.vessel_file) if getattr(args, "vessel_file", None) else None
    cls = getattr(args, "vessel", None)
    if ship is not None and cls is not None:
        ship = dataclasses.replace(ship, ice_class=as_vessel(cls).ice_class)
    return as_vessel(
        ship if ship is not None else cls,
        getattr(args, "speed", None),
        displacement_t=getattr(args, "displacement", None),
        draft_m=getattr(args, "draft", None),
        ukc_m=getattr(args, "ukc", None),
    )
