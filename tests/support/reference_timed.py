"""An independent reference for legs sailed on the clock (nothing here calls seaway): a leg is
sampled densely along its path (lat/lon charts: the great circle through index space, as a
polyline with a vertex every <= 4 pixels; planar charts: the straight segment),
and the ship is moved sample by sample, each stretch at the speed of the pixel it lies in,
read at the time the ship entered that pixel (the ice chart valid then, the weather then on
the course of the path across that pixel); the leg is closed where a sample touches land or a pixel the model
closes at the time the ship is at that sample.

It reports whether the leg only grazes a closed pixel (within 1e-3 pixel of one: a corner the
samples step over), where the C++ pricer's exact test may close it."""

from __future__ import annotations

import math

import numpy as np

from support.reference_weather import KM_PER_NM, KNOTS_PER_MS

R_KM = 6371.0088


class Grid:
    """A chart's geometry: lat/lon axes (regular) or planar pixel sizes dy, dx (km)."""

    def __init__(self, lat=None, lon=None, dy=None, dx=None):
        self.geographic = lat is not None
        if self.geographic:
            self.lat0, self.dlat = float(lat[0]), float(lat[1] - lat[0])
            self.lon0, self.dlon = float(lon[0]), float(lon[1] - lon[0])
        else:
            self.dy, self.dx = dy, dx

    def samples(self, p, q, n):
        """(index-space points (n + 1, 2), lengths of the n stretches, their courses) along the
        leg's path: on lat/lon charts the great circle through index space as a polyline with a
        vertex every <= 4 pixels (the path the package's legs follow), straight between them;
        a stretch's length is its share of its polyline piece's great-circle length."""
        p, q = np.asarray(p, float), np.asarray(q, float)
        if not self.geographic:
            pts = p + np.linspace(0.0, 1.0, n + 1)[:, None] * (q - p)
            d = np.diff(pts, axis=0)
            return pts, np.hypot(d[:, 0] * self.dy, d[:, 1] * self.dx), np.zeros(n)
        span = float(np.hypot(*(q - p)))
        m = 1 if span <= 4.0 else int(math.ceil(span / 4.0))
        corners = self._great_circle(p, q, m)
        per = max(n // m, 1)
        pts, length = [corners[:1]], []
        for a, b in zip(corners[:-1], corners[1:]):
            f = np.linspace(0.0, 1.0, per + 1)[1:, None]
            pts.append(a + f * (b - a))
            length.append(np.full(per, self._km(a, b) / per))
        pts = np.concatenate(pts)
        # Each stretch on the course of its piece: the great-circle course from where the path
        # enters its pixel (or turns, at a polyline vertex) to where it leaves it (or turns).
        pixel = np.floor((pts[:-1] + pts[1:]) / 2 + 0.5).astype(np.int64)
        segment = np.repeat(np.arange(m), per)
        cut = np.flatnonzero(np.any(np.diff(pixel, axis=0) != 0, axis=1) | (np.diff(segment) != 0)) + 1
        first, last = np.concatenate([[0], cut]), np.concatenate([cut, [len(pixel)]])
        a, b = pts[first], pts[last]
        la1, la2 = np.radians(self.lat0 + a[:, 0] * self.dlat), np.radians(self.lat0 + b[:, 0] * self.dlat)
        dlo = np.radians((b[:, 1] - a[:, 1]) * self.dlon)
        course = np.arctan2(
            np.sin(dlo) * np.cos(la2), np.cos(la1) * np.sin(la2) - np.sin(la1) * np.cos(la2) * np.cos(dlo)
        )
        return pts, np.concatenate(length), np.repeat(course, last - first)

    def _great_circle(self, p, q, m):
        """m + 1 points of the great circle p -> q (index space), ends exact."""
        if m == 1:
            return np.array([p, q])
        lat = np.radians(self.lat0 + np.array([p[0], q[0]]) * self.dlat)
        lon = np.radians(self.lon0 + np.array([p[1], q[1]]) * self.dlon)
        xyz = np.column_stack([np.cos(lat) * np.cos(lon), np.cos(lat) * np.sin(lon), np.sin(lat)])
        omega = math.acos(min(1.0, float(xyz[0] @ xyz[1])))
        f = np.linspace(0.0, 1.0, m + 1)
        v = (np.sin((1 - f) * omega)[:, None] * xyz[0] + np.sin(f * omega)[:, None] * xyz[1]) / math.sin(
            omega
        )
        la = np.degrees(np.arctan2(v[:, 2], np.hypot(v[:, 0], v[:, 1])))
        lo = np.degrees(lon[0] + np.unwrap(np.arctan2(v[:, 1], v[:, 0]) - lon[0]))
        out = np.column_stack([(la - self.lat0) / self.dlat, (lo - self.lon0) / self.dlon])
        out[0], out[-1] = p, q
        return out

    def _km(self, a, b):
        la1, la2 = np.radians(self.lat0 + np.array([a[0], b[0]]) * self.dlat)
        dlo = math.radians((b[1] - a[1]) * self.dlon)
        x = math.sin((la2 - la1) / 2) ** 2 + math.cos(la1) * math.cos(la2) * math.sin(dlo / 2) ** 2
        return 2 * R_KM * math.asin(math.sqrt(min(max(x, 0.0), 1.0)))


def sail(grid, p, q, t0, hours_per_km, is_open, land, n=20000):
    """(arrival hours, grazes) of the leg p -> q left at t0 without waiting, in about n stretches.

    hours_per_km(pixel, entered_h, course_rad) -> hours per km in that pixel for a ship that
    entered it at entered_h (inf: closed); is_open(pixel, t_h) -> bool; land: (rows, cols) bool,
    the pixels closed whatever the time."""
    pts, length, course = grid.samples(p, q, n)
    mid = np.floor((pts[:-1] + pts[1:]) / 2 + 0.5).astype(np.int64)
    rows, cols = land.shape
    off = (mid[:, 0] < 0) | (mid[:, 0] >= rows) | (mid[:, 1] < 0) | (mid[:, 1] >= cols)
    if off.any() or land[mid[:, 0], mid[:, 1]].any():
        return math.inf, False
    # Runs of stretches in one pixel on one course: one speed each.
    cut = np.flatnonzero(np.any(np.diff(mid, axis=0) != 0, axis=1) | (np.diff(course) != 0)) + 1
    t, times, entered, here = t0, [np.array([t0])], t0, None
    for a, b in zip(np.concatenate([[0], cut]), np.concatenate([cut, [len(length)]])):
        pixel = (int(mid[a, 0]), int(mid[a, 1]))
        if pixel != here:
            here, entered = pixel, t
        rate = hours_per_km(pixel, entered, float(course[a]))
        if not rate < math.inf:
            return math.inf, False
        times.append(t + np.cumsum(length[a:b]) * rate)
        t = float(times[-1][-1])
    times = np.concatenate(times)

    def closed(margin):
        for dr in (-margin, margin):
            for dc in (-margin, margin):
                r = np.floor(pts[:, 0] + 0.5 + dr).astype(np.int64)
                c = np.floor(pts[:, 1] + 0.5 + dc).astype(np.int64)
                off = (r < 0) | (r >= rows) | (c < 0) | (c >= cols)
                if off.any() or land[r, c].any():
                    return True
                for k in np.unique(np.column_stack([r, c]), axis=0):
                    at = (r == k[0]) & (c == k[1])
                    if not all(is_open((int(k[0]), int(k[1])), float(x)) for x in _spread(times[at])):
                        return True
        return False

    if closed(1e-9):
        return math.inf, False
    return float(t), closed(1e-3)


def _spread(times, most=64):
    """At most `most` of the times a pixel is held, its first and last among them."""
    if times.size <= most:
        return times
    return times[np.unique(np.linspace(0, times.size - 1, most).round().astype(int))]


def season_rate(h, valid_from_h):
    """hours_per_km for a season of charts h (frames, rows, cols), chart k from valid_from_h[k]."""

    def rate(pixel, entered, course):
        k = max(int(np.searchsorted(valid_from_h, entered, side="right")) - 1, 0)
        return float(h[k][pixel])

    return rate


def season_open(h, valid_from_h):
    def is_open(pixel, t):
        k = max(int(np.searchsorted(valid_from_h, t, side="right")) - 1, 0)
        return bool(np.isfinite(h[k][pixel]))

    return is_open


def speed_in(weather, pixel, t, course, v0):
    """Speed over ground (kn) in one pixel on `course` from a speed v0 through calm water, the
    weather (support.reference_weather.Weather) read at t: Khokhlov's loss, the current holding
    the track (Olovyannikov 2025); 0 beyond the limits."""
    if "wind" in weather.f and weather.at("wind", t, pixel) > weather.max_wind:
        return 0.0
    v = v0
    if "hs" in weather.f:
        hs = weather.at("hs", t, pixel)
        if hs > weather.max_wave:
            return 0.0
        if weather.khokhlov:
            frm = math.radians(weather.at("wdir", t, pixel)) if "wdir" in weather.f else course
            q = abs(math.remainder(frm - course, 2 * math.pi))
            h3 = 1.32 * hs
            v = v - (0.745 * h3 - 0.275 * q * h3) * (1 - 1.35e-6 * weather.d * v)
    if "ce" in weather.f:
        ce, cn = weather.at("ce", t, pixel) * KNOTS_PER_MS, weather.at("cn", t, pixel) * KNOTS_PER_MS
        along = cn * math.cos(course) + ce * math.sin(course)
        cross = ce * math.cos(course) - cn * math.sin(course)
        if abs(cross) >= v:
            return 0.0
        v = along + math.sqrt(v * v - cross * cross)
    return v if v > 1e-9 else 0.0


def weather_rate(weather, v0_kn, ice=None):
    """hours_per_km through the weather at v0_kn through calm water, or (ice = (h, valid_from_h))
    at the speed of the ice chart valid when the ship entered the pixel."""

    def rate(pixel, entered, course):
        v0 = v0_kn
        if ice is not None:
            h = season_rate(*ice)(pixel, entered, course)
            if not h < math.inf:
                return math.inf
            v0 = 1.0 / (KM_PER_NM * h)
        sog = speed_in(weather, pixel, entered, course, v0)
        return 1.0 / (KM_PER_NM * sog) if sog > 0 else math.inf

    return rate


def weather_open(weather, ice=None):
    def is_open(pixel, t):
        if ice is not None and not season_open(*ice)(pixel, t):
            return False
        ok = not ("wind" in weather.f and not weather.at("wind", t, pixel) <= weather.max_wind)
        return ok and not ("hs" in weather.f and not weather.at("hs", t, pixel) <= weather.max_wave)

    return is_open
