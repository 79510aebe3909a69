"""The `seaway bench` command: times the engine on the synthetic benchmark chart."""

from __future__ import annotations

import statistics
import time

from ..engine.api import route
from ..samples import synthetic_endpoints, synthetic_sea
from .common import CLI_METHODS, EPILOG, Progress, neighbourhood, size


def run_bench(args) -> int:
    say = Progress("bench", args.quiet)
    shape = tuple(args.size)
    say(f"building the synthetic chart seaway.samples.synthetic_sea({shape})")
    t = time.perf_counter()
    cost = synthetic_sea(shape)
    built = time.perf_counter() - t
    start, end = synthetic_endpoints(shape)
    print(
        f"seaway bench: synthetic_sea {shape[0]} x {shape[1]} pixels (30 % land, costs 1-30), "
        f"built in {built:.2f} s; {start} -> {end}, edge cost mean"
    )
    print(
        f"{'method':10s} {'k':>3s} {'median s':>9s} {'min s':>8s} {'settled':>11s} "
        f"{'B/pixel':>8s} {'cost':>12s}"
    )
    for k in args.neighbourhood:
        for method in args.method:
            times = []
            for i in range(args.repeat):
                say(f"{method} k={k}: run {i + 1} of {args.repeat}")
                t = time.perf_counter()
                r = route(cost, start, end, neighbourhood=k, method=method, edge_cost="mean")
                times.append(time.perf_counter() - t)
            print(
                f"{method:10s} {k:3d} {statistics.median(times):9.3f} {min(times):8.3f} "
                f"{r.stats.search.settled:11,d} {r.stats.search.state_bytes / cost.size:8.1f} "
                f"{r.cost:12.2f}",
                flush=True,
            )
    return 0


def add_bench_command(commands) -> None:
    bp = commands.add_parser(
        "bench",
        help="time the engine on the synthetic benchmark chart",
        description="Time seaway.route on seaway.samples.synthetic_sea (30 %% land, costs 1-30), "
        "south-west to north-east, and print the median time, pixels settled and "
        "search memory per pixel.",
        epilog=EPILOG,
    )
    bp.add_argument(
        "--size",
        type=size,
        default=(1900, 2300),
        metavar="ROWSxCOLS",
        help="chart size (default 1900x2300, Grinyak et al. 2022's Kara Sea chart)",
    )
    bp.add_argument(
        "--neighbourhood",
        type=neighbourhood,
        nargs="+",
        default=[5],
        metavar="K",
        help="stencil sizes to time (default 5)",
    )
    bp.add_argument(
        "--method",
        nargs="+",
        default=["auto", "dijkstra"],
        choices=CLI_METHODS,
        help="methods to time (default auto and dijkstra)",
    )
    bp.add_argument(
        "--repeat", type=int, default=3, metavar="N", help="runs per case; the median is reported (default 3)"
    )
    bp.add_argument("-q", "--quiet", action="store_true", help="no progress messages on stderr")
