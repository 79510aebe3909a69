"""Command line: ``seaway route CHART --from LAT,LON --to LAT,LON`` routes a ship across a chart
file; ``seaway demo`` through the built-in synthetic winter Kara Sea chart, from the Kara Gate to
the Vilkitsky Strait; ``seaway bench`` times the engine on the synthetic benchmark chart;
``seaway season DATE=CHART ... --from LAT,LON --to LAT,LON`` routes through dated ice charts."""

from __future__ import annotations

import argparse
import json
import os
import sys
import time

import numpy as np

from . import _cli, _cli_season, charts
from ._engine import route
from .errors import NoRouteError

KM_PER_NM = 1.852
#: (name, lat, lon) of the demo's ends; each is snapped to the nearest water pixel of the chart.
KARA_GATE = ("Kara Gate", 70.3, 58.5)
VILKITSKY_STRAIT = ("Vilkitsky Strait", 77.7, 104.0)


def _neighbourhood(text: str) -> int:
    try:
        k = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be an odd integer from 3 to 15, got {text!r}") from None
    if k < 3 or k > 15 or k % 2 == 0:
        raise argparse.ArgumentTypeError(f"must be an odd integer from 3 to 15, got {k}")
    return k


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="seaway", description="Least-cost ship routes through sea ice, waves and weather on "
        "raster charts.", epilog=_cli.EPILOG + " 'seaway COMMAND --help' explains each command.")
    commands = parser.add_subparsers(dest="command", required=True, metavar="command")
    demo = commands.add_parser(
        "demo", help="route Kara Gate -> Vilkitsky Strait on the built-in winter chart",
        description="Route a ship of an ice class from the Kara Gate to the Vilkitsky Strait "
                    "through synthetic winter ice on the real coastline (seaway.charts.kara_sea), "
                    "with paper 000's impact tables, and print a summary.")
    classes = charts.ice_classes.class_names()
    demo.add_argument("--ice-class", default="Arc7", choices=classes,
                      help="Russian Register ice class of the vessel (default Arc7)")
    demo.add_argument("--neighbourhood", type=_neighbourhood, default=5, metavar="K",
                      help="k of the k x k stencil: odd, 3 to 15 (default 5, as in paper 000)")
    demo.add_argument("--method", default="auto", choices=("auto", "bidirectional", "astar", "dijkstra"),
                      help="search algorithm (all exact; default auto: the fastest for the query)")
    demo.add_argument("--out", metavar="FILE", help="also write the route as GeoJSON to FILE")
    _cli.add_commands(commands, _neighbourhood)
    _cli_season.add_season_command(commands, _neighbourhood)
    return parser


def nearest_water(ds, lat: float, lon: float) -> tuple[int, int, float]:
    """(row, col, km moved) of the pixel holding (lat, lon) if it is water, else of the water pixel
    whose centre is nearest (great-circle distance) to (lat, lon)."""
    la, lo = ds.lat.values, ds.lon.values
    r, c = int(np.abs(la - lat).argmin()), int(np.abs(lo - lon).argmin())
    if not ds.land.values[r, c]:
        return r, c, 0.0
    water = np.argwhere(~ds.land.values)
    if water.size == 0:
        raise ValueError("the chart has no water pixel")
    p, q = np.radians(la[water[:, 0]]), np.radians(lo[water[:, 1]])
    a = np.sin((p - np.radians(lat)) / 2) ** 2 + np.cos(p) * np.cos(np.radians(lat)) * np.sin(
        (q - np.radians(lon)) / 2) ** 2
    km = 2 * charts.EARTH_RADIUS_KM * np.arcsin(np.sqrt(np.minimum(a, 1.0)))
    i = int(np.argmin(km))
    return int(water[i, 0]), int(water[i, 1]), float(km[i])


def _end(ds, u, place, ice_class):
    """Snap a named place to the nearest water pixel and check the vessel may enter its ice."""
    name, lat, lon = place
    r, c, moved = nearest_water(ds, lat, lon)
    pla, plo = float(ds.lat[r]), float(ds.lon[c])
    note = ("water" if moved == 0 else
            f"{lat:g} N {lon:g} E is land: snapped {moved:.1f} km to the nearest water pixel")
    if not np.isfinite(u[r, c]):
        code = int(ds.stage_of_development.values[r, c])
        raise NoRouteError(
            f"an {ice_class} vessel may not enter the ice at the {name} ({charts.STAGES[code][0]}, "
            f"WMO stage {code}, at {pla:.4f} N {plo:.4f} E); no route. Try --ice-class Arc7")
    return (pla, plo), f"{pla:.4f} N {plo:.4f} E ({name}; {note})"


def _pixel_km(ds) -> float:
    return abs(float(ds.lat[1] - ds.lat[0])) * charts.KM_PER_DEG


def demo(args) -> int:
    t0 = time.perf_counter()
    ds = charts.kara_sea()
    t_chart = time.perf_counter() - t0
    u = charts.ice_impact(ds.stage_of_development, args.ice_class)
    start, start_text = _end(ds, u.values, KARA_GATE, args.ice_class)
    end, end_text = _end(ds, u.values, VILKITSKY_STRAIT, args.ice_class)
    t1 = time.perf_counter()
    r = route(u, start, end, land=ds.land, neighbourhood=args.neighbourhood, method=args.method)
    t_search = time.perf_counter() - t1
    km = r.length
    rows, cols = ds.land.shape
    e = charts.KARA_EXTENT
    first, last = r.coords[0], r.coords[-1]
    print("seaway demo: Kara Gate -> Vilkitsky Strait through synthetic winter ice")
    print(f"chart:        {rows} x {cols} pixels, {e['lat_south']:g}-{e['lat_north']:g} N "
          f"{e['lon_west']:g}-{e['lon_east']:g} E, {_pixel_km(ds):.2f} km north-south; "
          f"built in {t_chart:.2f} s")
    print(f"source:       {ds.attrs['source']}")
    print(f"vessel class: {args.ice_class} (impact u from paper 000, "
          f"{'Table 3' if args.ice_class == 'Arc5' else 'Table 2'})")
    print(f"start:        {start_text}")
    print(f"end:          {end_text}")
    print(f"route cost:   {r.cost:.1f} (sum of u x km)")
    print(f"length:       {km:.1f} km = {km / KM_PER_NM:.1f} nm")
    print(f"waypoints:    {len(r.pixels)}")
    print(f"search:       {r.method}, {args.neighbourhood}x{args.neighbourhood} neighbourhood, "
          f"{t_search:.2f} s, {r.stats['settled']} pixels settled")
    t2 = time.perf_counter()
    sm = r.smoothed()
    print(f"smoothed:     cost {sm.cost:.1f} ({100 * (sm.cost / r.cost - 1):+.2f} %), "
          f"{r.course_changes} -> {sm.course_changes} course changes, in {time.perf_counter() - t2:.3f} s")
    print(f"first:        {first[0]:.4f} N {first[1]:.4f} E")
    print(f"last:         {last[0]:.4f} N {last[1]:.4f} E")
    if args.out:
        feature = r.to_geojson()
        feature["properties"].update(ice_class=args.ice_class, start=KARA_GATE[0],
                                     end=VILKITSKY_STRAIT[0], chart=ds.attrs["title"])
        _write_atomically(args.out, json.dumps(feature))
        print(f"written:      {args.out}")
    return 0


def _write_atomically(path: str, text: str) -> None:
    """Write to a temporary file beside `path`, then rename: never a half-written file."""
    from .export import write_atomically
    write_atomically(path, text)


def main(argv=None) -> int:
    args = _parser().parse_args(argv)
    run = {"demo": demo, "route": _cli.run_route, "bench": _cli.run_bench,
           "season": _cli_season.run_season}[args.command]
    try:
        return run(args)
    except (NoRouteError, ValueError, OSError, ImportError) as exc:
        print(f"seaway {args.command}: error: {exc}", file=sys.stderr)
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


if __name__ == "__main__":
    entry()
