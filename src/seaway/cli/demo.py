"""The `seaway demo` command: the built-in synthetic winter Kara Sea chart, from the Kara Gate
to the Vilkitsky Strait, for an ice class."""

from __future__ import annotations

import json
import re
import time

from .. import samples as charts
from ..base.files import write_atomically
from ..base.units import KM_PER_DEG, KM_PER_NM
from ..voyage import open_chart
from .common import CLI_METHODS, neighbourhood

#: (name, lat, lon) of the demo's ends; an end the ship may not use moves at most DEMO_SNAP_KM.
KARA_GATE = ("Kara Gate", 70.3, 58.5)
VILKITSKY_STRAIT = ("Vilkitsky Strait", 77.7, 104.0)
DEMO_SNAP_KM = 30.0


def _end(r, which, place) -> str:
    """How the route's start or end reads: where it is, and how far it was moved (its note)."""
    name, lat, lon = place
    pla, plo = (float(v) for v in r.coords[0 if which == "start" else -1])
    moved = next((re.search(r"moved ([0-9.]+ km)", n) for n in r.notes if n.startswith(which + " ")), None)
    note = "water" if moved is None else f"{lat:g} N {lon:g} E is not usable: moved {moved.group(1)}"
    return f"{pla:.4f} N {plo:.4f} E ({name}; {note})"


def _pixel_km(ds) -> float:
    return abs(float(ds.lat[1] - ds.lat[0])) * KM_PER_DEG


def demo(args) -> int:
    t0 = time.perf_counter()
    chart = open_chart("kara", vessel=args.ice_class)
    ds = chart.layers
    t_chart = time.perf_counter() - t0
    t1 = time.perf_counter()
    r = chart.route(
        KARA_GATE[1:],
        VILKITSKY_STRAIT[1:],
        snap_km=DEMO_SNAP_KM,
        escort=True,  # a ship known by its class alone passes 1.4 m (Arc7): thicker ice is escorted
        neighbourhood=args.neighbourhood,
        method=args.method,
        smooth=False,
        compare=False,
    )
    t_search = time.perf_counter() - t1
    km = r.length
    rows, cols = ds.land.shape
    e = charts.KARA_EXTENT
    first, last = r.coords[0], r.coords[-1]
    print("seaway demo: Kara Gate -> Vilkitsky Strait through synthetic winter ice")
    print(
        f"chart:        {rows} x {cols} pixels, {e['lat_south']:g}-{e['lat_north']:g} N "
        f"{e['lon_west']:g}-{e['lon_east']:g} E, {_pixel_km(ds):.2f} km north-south; "
        f"built in {t_chart:.2f} s"
    )
    print(f"source:       {ds.attrs['source']}")
    print(
        f"vessel class: {args.ice_class} (impact u from Grinyak et al. 2022, "
        f"{'Table 3' if args.ice_class == 'Arc5' else 'Table 2'})"
    )
    print(f"start:        {_end(r, 'start', KARA_GATE)}")
    print(f"end:          {_end(r, 'end', VILKITSKY_STRAIT)}")
    print(f"route cost:   {r.cost:.1f} (sum of u x km)")
    print(f"length:       {km:.1f} km = {km / KM_PER_NM:.1f} nm")
    print(f"waypoints:    {len(r.waypoint_index)} (ends and course changes; {len(r.pixels)} pixels)")
    s = r.summary()
    print(
        f"time:         {s['time_h']:.1f} h at {s['speed_kn']:g} kn in open water (Andreeva 2021's speed in "
        f"ice), {s.get('escorted_km', 0.0):.0f} km under icebreaker escort at 6 kn"
    )
    print(
        f"search:       {r.method}, {args.neighbourhood}x{args.neighbourhood} neighbourhood, "
        f"{t_search:.2f} s, {r.stats.search.settled} pixels settled"
    )
    t2 = time.perf_counter()
    sm = r.smoothed()
    print(
        f"smoothed:     cost {sm.cost:.1f} ({100 * (sm.cost / r.cost - 1):+.2f} %), "
        f"{r.course_changes} -> {sm.course_changes} course changes, in {time.perf_counter() - t2:.3f} s"
    )
    print(f"first:        {first[0]:.4f} N {first[1]:.4f} E")
    print(f"last:         {last[0]:.4f} N {last[1]:.4f} E")
    if args.out:
        feature = r.to_geojson()
        feature["properties"].update(
            ice_class=args.ice_class, start=KARA_GATE[0], end=VILKITSKY_STRAIT[0], chart=ds.attrs["title"]
        )
        write_atomically(args.out, json.dumps(feature))
        print(f"written:      {args.out}")
    return 0


def add_demo_command(commands) -> None:
    demo = commands.add_parser(
        "demo",
        help="route Kara Gate -> Vilkitsky Strait on the built-in winter chart",
        description="Route a ship of an ice class from the Kara Gate to the Vilkitsky Strait "
        "through synthetic winter ice on the real coastline (seaway.samples.kara_sea), "
        "with Grinyak et al. 2022's impact tables, and print a summary.",
    )
    classes = charts.ice_classes.class_names()
    demo.add_argument(
        "--ice-class",
        default="Arc7",
        choices=classes,
        help="Russian Register ice class of the vessel (default Arc7)",
    )
    demo.add_argument(
        "--neighbourhood",
        type=neighbourhood,
        default=5,
        metavar="K",
        help="k of the k x k stencil: odd, 3 to 15 (default 5, as in Grinyak et al. 2022)",
    )
    demo.add_argument(
        "--method",
        default="auto",
        choices=CLI_METHODS,
        help="search algorithm (all exact; default auto: the fastest for the query)",
    )
    demo.add_argument("--out", metavar="FILE", help="also write the route as GeoJSON to FILE")
