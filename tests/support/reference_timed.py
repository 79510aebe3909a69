"""An independent reference for legs sailed on the clock (nothing here calls seaway): a leg is
sampled densely along its path (lat/lon charts: the great circle through index space, as a
polyline with a vertex every <= 4 pixels; planar charts: the straight segment) and read as the
chain of the pixels the samples fall in: the move from pixel a to the next, b, runs from the
middle of a's stretch of the leg to the middle of b's (from the leg's start, to its end, for
the first and last), is priced as one step from a to b started when the ship starts the move
(the ice chart valid then, the mean of a's and b's weather then, on the course from the move's
start to its end), and every pixel a sample of the move touches must be open through the whole
move (checked at 33 times); land or a pixel off the chart closes the leg.

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
        """(index-space points, lengths of the stretches between them: about n) along the
        leg's path: on lat/lon charts the great circle through index space as a polyline with a
        vertex every <= 4 pixels (the path the package's legs follow), straight between them;
        a stretch's length is its share of its polyline piece's great-circle length."""
        p, q = np.asarray(p, float), np.asarray(q, float)
        if not self.geographic:
            pts = p + np.linspace(0.0, 1.0, n + 1)[:, None] * (q - p)
            d = np.diff(pts, axis=0)
            return pts, np.hypot(d[:, 0] * self.dy, d[:, 1] * self.dx)
        span = float(np.hypot(*(q - p)))
        m = 1 if span <= 4.0 else int(math.ceil(span / 4.0))
        corners = self._great_circle(p, q, m)
        per = max(n // m, 1)
        pts, length = [corners[:1]], []
        for a, b in zip(corners[:-1], corners[1:]):
            f = np.linspace(0.0, 1.0, per + 1)[1:, None]
            pts.append(a + f * (b - a))
            length.append(np.full(per, self._km(a, b) / per))
        return np.concatenate(pts), np.concatenate(length)

    def course(self, a, b):
        """The initial great-circle course (radians) from a to b (index space); 0 on planar grids."""
        if not self.geographic:
            return 0.0
        la1, la2 = np.radians(self.lat0 + np.array([a[0], b[0]]) * self.dlat)
        dl = math.radians((b[1] - a[1]) * self.dlon)
        return math.atan2(
            math.sin(dl) * math.cos(la2),
            math.cos(la1) * math.sin(la2) - math.sin(la1) * math.cos(la2) * math.cos(dl),
        )

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


def sail(grid, p, q, t0, move_hours, is_open, land, n=20000):
    """(arrival hours, grazes) of the leg p -> q left at t0 without waiting, in about n stretches.

    move_hours(a, b, la, lb, course, t) -> hours of the step from pixel a (la km of it) to pixel
    b (lb km) started at t (inf: closed); is_open(pixel, t) -> bool; land: (rows, cols) bool, the
    pixels closed whatever the time."""
    pts, length = grid.samples(p, q, n)
    mid = np.floor((pts[:-1] + pts[1:]) / 2 + 0.5).astype(np.int64)
    rows, cols = land.shape
    off = (mid[:, 0] < 0) | (mid[:, 0] >= rows) | (mid[:, 1] < 0) | (mid[:, 1] >= cols)
    if off.any() or land[mid[:, 0], mid[:, 1]].any():
        return math.inf, False
    s = np.concatenate([[0.0], np.cumsum(length)])
    cut = np.flatnonzero(np.any(np.diff(mid, axis=0) != 0, axis=1)) + 1
    first, last = np.concatenate([[0], cut]), np.concatenate([cut, [len(length)]])
    pixel = [(int(mid[i, 0]), int(mid[i, 1])) for i in first]
    size = s[last] - s[first]
    middle = (s[first] + s[last]) / 2
    cells = len(first)
    t, moves = t0, []
    for i in range(max(cells - 1, 1)):
        j = min(i + 1, cells - 1)
        la = size[i] if i == 0 else size[i] / 2
        lb = 0.0 if cells == 1 else (size[j] if i + 2 == cells else size[j] / 2)
        d0, d1 = (0.0 if i == 0 else middle[i]), (s[-1] if i + 2 >= cells else middle[j])
        at = [np.array([np.interp(d, s, pts[:, k]) for k in (0, 1)]) for d in (d0, d1)]
        h = move_hours(pixel[i], pixel[j], la, lb, grid.course(*at), t)
        if not h < math.inf:
            return math.inf, False
        moves.append((d0, d1, t, t + h))
        t += h

    def closed(margin):
        for d0, d1, ta, tb in moves:
            inside = (s >= d0 - 1e-12) & (s <= d1 + 1e-12)
            x = pts[inside]
            near = set()
            for dr in (-margin, margin):
                for dc in (-margin, margin):
                    r = np.floor(x[:, 0] + 0.5 + dr).astype(np.int64)
                    c = np.floor(x[:, 1] + 0.5 + dc).astype(np.int64)
                    if ((r < 0) | (r >= rows) | (c < 0) | (c >= cols)).any() or land[r, c].any():
                        return True
                    near |= set(zip(r.tolist(), c.tolist()))
            times = np.linspace(ta, tb, 33)
            if not all(is_open(px, float(tt)) for px in near for tt in times):
                return True
        return False

    if closed(1e-9):
        return math.inf, False
    return float(t), closed(1e-3)


def frame(valid_from_h, t):
    return max(int(np.searchsorted(valid_from_h, t, side="right")) - 1, 0)


def season_move(h, valid_from_h):
    """move_hours through a season of charts h (frames, rows, cols), chart k from valid_from_h[k]."""

    def hours(a, b, la, lb, course, t):
        k = frame(valid_from_h, t)
        return la * float(h[k][a]) + (lb * float(h[k][b]) if lb > 0 else 0.0)

    return hours


def season_open(h, valid_from_h):
    def is_open(pixel, t):
        return bool(np.isfinite(h[frame(valid_from_h, t)][pixel]))

    return is_open


def speed_between(weather, a, b, t, course, v0):
    """Speed over ground (kn) of a step from pixel a to pixel b on `course` from a speed v0
    through calm water, the weather (support.reference_weather.Weather) read at t at both ends:
    Khokhlov's loss in the mean waves, the mean current holding the track (Olovyannikov 2025); 0
    beyond the limits."""
    at = weather.at
    if "wind" in weather.f and max(at("wind", t, a), at("wind", t, b)) > weather.max_wind:
        return 0.0
    v = v0
    if "hs" in weather.f:
        ha, hb = at("hs", t, a), at("hs", t, b)
        if max(ha, hb) > weather.max_wave:
            return 0.0
        if weather.khokhlov:
            q = 0.0
            if "wdir" in weather.f:
                x, y = math.radians(at("wdir", t, a)), math.radians(at("wdir", t, b))
                frm = math.atan2(math.sin(x) + math.sin(y), math.cos(x) + math.cos(y))
                q = abs(math.remainder(frm - course, 2 * math.pi))
            h3 = 1.32 * 0.5 * (ha + hb)
            v = v - (0.745 * h3 - 0.275 * q * h3) * (1 - 1.35e-6 * weather.d * v)
    if "ce" in weather.f:
        ce = 0.5 * (at("ce", t, a) + at("ce", t, b)) * KNOTS_PER_MS
        cn = 0.5 * (at("cn", t, a) + at("cn", t, b)) * KNOTS_PER_MS
        along = cn * math.cos(course) + ce * math.sin(course)
        cross = ce * math.cos(course) - cn * math.sin(course)
        if abs(cross) >= v:
            return 0.0
        v = along + math.sqrt(v * v - cross * cross)
    return v if v > 1e-9 else 0.0


def weather_move(weather, v0_kn, ice=None):
    """move_hours through the weather at v0_kn through calm water, or (ice = (h, valid_from_h))
    at the move's speed through the ice of the chart valid when it starts."""

    def hours(a, b, la, lb, course, t):
        v0 = v0_kn
        if ice is not None:
            ice_h = season_move(*ice)(a, b, la, lb, course, t)
            if not ice_h < math.inf:
                return math.inf
            v0 = (la + lb) / KM_PER_NM / ice_h
        sog = speed_between(weather, a, b, t, course, v0)
        return (la + lb) / KM_PER_NM / sog if sog > 0 else math.inf

    return hours


def weather_open(weather, ice=None):
    def is_open(pixel, t):
        if ice is not None and not season_open(*ice)(pixel, t):
            return False
        ok = not ("wind" in weather.f and not weather.at("wind", t, pixel) <= weather.max_wind)
        return ok and not ("hs" in weather.f and not weather.at("hs", t, pixel) <= weather.max_wave)

    return is_open
