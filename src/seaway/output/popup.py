"""The popup of a waypoint on the HTML map (seaway.output.webmap): its position (degrees and
minutes), the ends asked for, its ETA and ETD on a clock, and the leg that starts there: course,
distance, time, cost and the ice along it."""

from __future__ import annotations

import html

import numpy as np

from ..result.environment import Category
from ..result.schedule import schedule, short


def _dms(value, pos, neg, width):
    hemi = pos if value >= 0 else neg
    deg, minutes = divmod(abs(value) * 60.0, 60.0)
    return f"{int(deg):0{width}d}&deg;{minutes:04.1f}'{hemi}"


def _ice_text(name, value):
    if isinstance(value, Category):
        return f"{name}: {'up to' if value.rule == 'governing' else 'mostly'} {value}"
    mean, high = value
    if not np.isfinite(high):
        return f"{name}: none"
    return f"{name}: mean {mean:.3g}, max {high:.3g}"


def waypoint_popup(route, number, point, leg, speed_kn):
    """The HTML of a waypoint's popup: its position and the leg that starts there."""
    if route.geographic:
        where = f"{_dms(point[0], 'N', 'S', 2)} {_dms(point[1] % 360 if point[1] > 180 else point[1], 'E', 'W', 3)}"
    else:
        where = f"y {point[0]:.6g}, x {point[1]:.6g}"
    lines = [f"<b>waypoint {number}</b>", where]
    last = number == len(route.waypoint_index)
    if route.requested is not None and (number == 1 or last):  # an end: the one asked for
        asked = route.requested[1 if last else 0]
        lines[0] = f"<b>waypoint {number}: {'end' if last else 'start'}</b>"
        lines.append(
            f"requested {_dms(asked[0], 'N', 'S', 2)} {_dms((asked[1] + 180) % 360 - 180, 'E', 'W', 3)}"
            if route.geographic
            else f"requested {asked[0]:g}, {asked[1]:g}"
        )
        lines += [html.escape(n) for n in route.notes if n.startswith("end " if last else "start ")]
    timed = schedule(route)
    if timed is not None and timed.departure is not None:  # the waypoint's ETA and ETD (UTC)
        i = int(route.waypoint_index[number - 1])
        if number > 1:
            lines.append(f"ETA {short(timed.eta(i))} UTC")
        if leg is not None:
            lines.append(f"ETD {short(timed.etd(i))} UTC")
    if leg is None:
        lines.append(
            f"end: {route.length:.1f} {'km' if route.geographic else 'units'}, "
            f"cost {route.cost:.6g} {html.escape(route.unit)}"
        )
        if timed is not None and timed.forecast:
            lines.append(f"forecast {html.escape(timed.forecast)}")
        if route.ice_speed is not None:
            hours = sum(leg.time_h for leg in route.legs())
            lines.append(
                html.escape(f"time {hours:.1f} h" if np.isfinite(hours) else "no time")
                + "; speed in ice: "
                + html.escape(route.ice_speed.model)
            )
    else:
        dist = (
            f"{leg.distance_nm:.2f} nm ({leg.distance:.2f} km)"
            if leg.distance_nm is not None
            else f"{leg.distance:.4g} units"
        )
        lines += [f"leg {leg.number}: course {leg.course:05.1f}&deg;, {dist}"]
        if leg.time_h is not None and route.ice_speed is not None:  # the speed in the ice
            lines.append(
                f"time {leg.time_h:.2f} h at {leg.speed_kn:.3g} kn (mean, in ice)"
                if np.isfinite(leg.time_h)
                else "no time: no speed in part of its ice"
            )
        elif leg.time_h is not None and timed is not None:  # on a clock: the real time
            made = f", {leg.speed_kn:.1f} kn made good" if leg.speed_kn is not None else ""
            lines.append(f"time {leg.time_h:.2f} h{made}")
        elif leg.time_h is not None:
            lines.append(f"time {leg.time_h:.2f} h at {speed_kn:g} kn")
        lines.append(f"cost {leg.cost:.6g} {html.escape(route.unit)}")
        lines += [html.escape(_ice_text(n, mv)) for n, mv in leg.environment.items()]
    return "<br>".join(lines)
