"""str(route): a summary line and a table of the legs, as a navigator reads a passage plan."""

from __future__ import annotations

import numpy as np

from .environment import CATEGORICAL, STAGES, Category, extreme_name
from .schedule import dated_schedule, short


def fmt_lat(v: float) -> str:
    """Degrees and decimal minutes, e.g. 70-18.00N."""
    d, m = divmod(round(abs(v) * 60, 2), 60)
    return f"{int(d):02d}-{m:05.2f}{'N' if v >= 0 else 'S'}"


def fmt_lon(v: float) -> str:
    v = (v + 180.0) % 360.0 - 180.0
    d, m = divmod(round(abs(v) * 60, 2), 60)
    return f"{int(d):03d}-{m:05.2f}{'E' if v >= 0 else 'W'}"


def fmt_point(p, geographic: bool) -> str:
    if geographic:
        return f"{fmt_lat(p[0])} {fmt_lon(p[1])}"
    return f"y {p[0]:.6g} x {p[1]:.6g}"


def fmt_hours(h: float) -> str:
    d, rest = divmod(h, 24.0)
    return f"{int(d)} d {rest:.1f} h" if d else f"{rest:.1f} h"


def route_table(route) -> str:
    legs = route.legs()
    geo = route.geographic
    s = route.summary()
    units = "km" if geo else "units"
    head = (
        f"{route.name}: {fmt_point(s['start'], geo)} -> {fmt_point(s['end'], geo)}; "
        f"{len(legs)} legs, {route.course_changes} course changes"
    )
    dist = f"{s['length']:.1f} {units}" + (f" ({s['length_nm']:.1f} nm)" if geo else "")
    lines = [
        head,
        f"distance {dist}; cost {route.cost:.6g} {route.unit} (edge cost {route.edge_cost!r}, "
        f"{route.neighbourhood}x{route.neighbourhood} stencil)",
    ]
    timed = route.stats.voyage is not None
    if timed:  # a route on a clock: its real time, departure and arrival
        lines.append(voyage_line(s))
    elif "speed_model" in s:  # times from the speed in the ice
        t = fmt_hours(s["time_h"]) if np.isfinite(s["time_h"]) else "none"
        lines.append(f"time: {t} ({s['speed_kn']:g} kn in open water; in ice {s['speed_model']})")
        if "departure" in s:
            lines.append(f"departure {s['departure']}, arrival {s['arrival']}")
        if s.get("escorted_km"):
            lines.append(
                f"under icebreaker escort: {s['escorted_km']:.1f} km ({s['escorted_km'] / 1.852:.1f} nm) on "
                f"leg{'s' if len(s['escorted_legs']) > 1 else ''} {', '.join(map(str, s['escorted_legs']))}"
            )
        if s.get("stopped_km"):
            lines.append(
                f"no time: the model gives no speed on {s['stopped_km']:.1f} km of the route "
                "(ice as thick as the class passes, or closed to it): an icebreaker's escort"
            )
    elif "time_h" in s and "departure" in s:
        lines[-1] += f"; {fmt_hours(s['time_h'])} at {s['speed_kn']:g} kn"
        lines.append(f"departure {s['departure']}, arrival {s['arrival']}")
    elif "time_h" in s:
        lines[-1] += f"; {fmt_hours(s['time_h'])} at {s['speed_kn']:g} kn"
    if "requested_start" in s:
        lines.insert(
            1, f"requested {fmt_point(s['requested_start'], geo)} -> {fmt_point(s['requested_end'], geo)}"
        )
    lines += [f"assumed: {a}" for a in route.assumptions]
    if np.isfinite(s.get("least_depth_m", np.nan)):
        lines.append(f"least depth {s['least_depth_m']:.1f} m at {fmt_point(s['least_depth_at'], geo)}")
    env = list(route.environment)
    # One time: a route on a clock shows its real hours (its cost, when in hours, is the same
    # figure and is left out), the speed made good under way and the arrival at each waypoint.
    dated = dated_schedule(route) is not None
    cost_col = "" if timed and route.unit == "h" else "cost"
    cols = [
        "leg",
        "from",
        "to",
        "course",
        "nm" if geo else "",
        units,
        "kn",
        "hours",
        "ETA (UTC)" if dated else "",
        "escort km" if any(leg.escorted_km for leg in legs) else "",
        cost_col,
    ]
    cols += [
        (
            f"{n} ({'governing' if n in STAGES else 'most frequent'})"
            if n in CATEGORICAL
            else f"{n} mean/{extreme_name(n)}"
        )
        for n in env
    ]
    rows = []
    for leg in legs:
        row = [
            str(leg.number),
            fmt_point(leg.start, geo),
            fmt_point(leg.end, geo),
            f"{leg.course:05.1f}",
            f"{leg.distance_nm:.1f}" if geo else "",
            f"{leg.distance:.1f}" if geo else f"{leg.distance:.4g}",
            (f"{leg.speed_kn:.1f}" if timed else f"{leg.speed_kn:.3g}") if leg.speed_kn is not None else "-",
            f"{leg.time_h:.1f}" if leg.time_h is not None else "-",
            short(leg.arrive) if dated else "",
            f"{leg.escorted_km:.1f}" if leg.escorted_km else "",
            f"{leg.cost:.5g}" if cost_col else "",
        ]
        for n in env:
            value = leg.environment[n]
            if isinstance(value, Category):
                row.append(str(value) if np.isfinite(value.code) else "-")
            else:
                row.append("-" if np.isnan(value[1]) else f"{value[0]:.3g}/{value[1]:.3g}")
        rows.append(row)
    keep = [k for k, c in enumerate(cols) if c or any(r[k] for r in rows)]
    cols = [cols[k] for k in keep]
    rows = [[r[k] for k in keep] for r in rows]
    width = [max(len(c), *(len(r[k]) for r in rows)) if rows else len(c) for k, c in enumerate(cols)]
    left = {"from", "to"}

    def line(cells):
        return "  ".join(
            c.ljust(w) if cols[k] in left else c.rjust(w) for k, (c, w) in enumerate(zip(cells, width))
        ).rstrip()

    lines += [line(cols)] + [line(r) for r in rows]
    return "\n".join(lines)


def voyage_line(s: dict) -> str:
    """The summary line of a route on a clock: departure, arrival, time, waits, forecast."""
    text = f"voyage {fmt_hours(s['time_h'])}"
    if "departure" in s:
        text = f"departure {s['departure']}, arrival {s['arrival']}: " + text
    if s.get("hours_waiting"):
        text += f" ({fmt_hours(s['hours_waiting'])} waiting)"
    text += f"; forecast {s['forecast']}" if "forecast" in s else ""
    if "hours_in_danger" in s:
        text += (
            f"\nthrough danger zones: {s['hours_in_danger']:.1f} h, the least possible "
            "(no route avoids them; Sotnikova 2009)"
        )
    return text
