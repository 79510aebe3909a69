"""The `seaway demo` command: the built-in synthetic winter Kara Sea chart, from the Kara Gate
to the Vilkitsky Strait, for an ice class."""

from __future__ import annotations

import json
import time

import numpy as np

from .. import samples as charts
from ..base.files import write_atomically
from ..base.sphere import distance_km
from ..base.units import KM_PER_DEG, KM_PER_NM
from ..engine.api import route
from ..errors import NoRouteError
from ..icenav.noroute import explain_no_route
from .common import CLI_METHODS, neighbourhood

#: (name, lat, lon) of the demo's ends; each is snapped to the nearest water pixel of the chart.
KARA_GATE = ("Kara Gate", 70.3, 58.5)
VILKITSKY_STRAIT = ("Vilkitsky Strait", 77.7, 104.0)


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
    km = distance_km(la[water[:, 0]], lo[water[:, 1]], lat, lon)
    i = int(np.argmin(km))
    return int(water[i, 0]), int(water[i, 1]), float(km[i])


def _end(ds, u, place, ice_class):
    """Snap a named place to the nearest water pixel and check the vessel may enter its ice."""
    name, lat, lon = place
    r, c, moved = nearest_water(ds, lat, lon)
    pla, plo = float(ds.lat[r]), float(ds.lon[c])
    note = (
        "water"
        if moved == 0
        else f"{lat:g} N {lon:g} E is land: snapped {moved:.1f} km to the nearest water pixel"
    )
    if not np.isfinite(u[r, c]):
        code = int(ds.stage_of_development.values[r, c])
        raise NoRouteError(
            f"an {ice_class} vessel may not enter the ice at the {name} ({charts.STAGES[code][0]}, "
            f"WMO stage {code}, at {pla:.4f} N {plo:.4f} E); no route. Try --ice-class Arc7"
        )
    return (pla, plo), f"{pla:.4f} N {plo:.4f} E ({name}; {note})"


def _pixel_km(ds) -> float:
    return abs(float(ds.lat[1] - ds.lat[0])) * KM_PER_DEG


def demo(args) -> int:
    t0 = time.perf_counter()
    ds = charts.kara_sea()
    t_chart = time.perf_counter() - t0
    u = charts.ice_impact(ds.stage_of_development, args.ice_class)
    start, start_text = _end(ds, u.values, KARA_GATE, args.ice_class)
    end, end_text = _end(ds, u.values, VILKITSKY_STRAIT, args.ice_class)
    t1 = time.perf_counter()
    try:
        r = route(u, start, end, land=ds.land, neighbourhood=args.neighbourhood, method=args.method)
    except NoRouteError:  # say why from the ice: what closes the way, which class gets through
        raise explain_no_route(
            ds, args.ice_class, start, end, cost=u, neighbourhood=args.neighbourhood
        ) from None
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
    print(f"start:        {start_text}")
    print(f"end:          {end_text}")
    print(f"route cost:   {r.cost:.1f} (sum of u x km)")
    print(f"length:       {km:.1f} km = {km / KM_PER_NM:.1f} nm")
    print(f"waypoints:    {len(r.pixels)}")
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
