"""The words that head a route's files: the header lines of a CSV file and the description of a
GPX or RTZ route (length, cost, time, the ends used and asked for, what the route assumes), and
longitudes as the files write them."""

from __future__ import annotations

import numpy as np

from ..result.waypoints import wrap180  # noqa: F401 - longitudes as the files write them


def header_lines(route, speed_kn=None) -> list:
    """The lines that head a route's file (CSV comments, GPX and RTZ descriptions): its length,
    cost and time; the ends used and those requested; what it assumes."""
    s = route.summary(speed_kn)
    geo_ = route.geographic
    size = f"{s['length_nm']:.1f} nm" if geo_ else f"{s['length']:.4g} {s['length_units']}"
    head = f"{route.name}: {size}, cost {route.cost:.6g} {route.unit}, {s['legs']} legs"
    if "speed_model" in s:
        head += f", {s['time_h']:.1f} h" if np.isfinite(s["time_h"]) else ", no time"
        lines = [head, f"speed in ice: {s['speed_model']}"]
        if s.get("stopped_km"):
            lines.append(f"no speed on {s['stopped_km']:.1f} km (an icebreaker's escort)")
    elif "departure" in s or route.stats.voyage is not None:  # a route on a clock: its real time
        head += f", {s['time_h']:.1f} h"
        lines = [head]
        if "departure" in s:
            lines.append(f"departure {s['departure']}, arrival {s['arrival']}")
        if "forecast" in s:
            lines.append(f"forecast {s['forecast']}")
        if "hours_in_danger" in s:
            lines.append(f"through danger zones {s['hours_in_danger']:.1f} h (no route avoids them)")
    else:
        if "time_h" in s:
            head += f", {s['time_h']:.1f} h at {s['speed_kn']:g} kn"
        lines = [head]
    for end in ("start", "end"):
        line = f"{end} {_point(s[end])}"
        if f"requested_{end}" in s:
            line += f" (requested {_point(s[f'requested_{end}'], None)})"
        lines.append(line)
    return lines + [f"assumed: {a}" for a in s.get("assumptions", ())]


def describe(route, speed_kn=None) -> str:
    """One paragraph for a GPX or RTZ description: header_lines joined."""
    return "; ".join(header_lines(route, speed_kn))


def _point(p, digits=5) -> str:
    return ",".join(f"{v:g}" if digits is None else f"{v:.{digits}f}" for v in p)
