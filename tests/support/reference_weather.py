"""An independent brute force for routes through ice and weather at once (nothing here calls
seaway): the weather's speed over ground written again from Olovyannikov 2025 (Khokhlov's speed
loss, the current holding the track) and the wind and wave limits, the ice's time through a
chart from the step's pieces (reference.pieces / touched), waiting for later charts, and the
earliest arrival over every simple path."""

from __future__ import annotations

import math

import numpy as np

from support.reference import best_arrival_over_paths, haversine, pieces, touched

KNOTS_PER_MS = 3600.0 / 1852.0
KM_PER_NM = 1.852


class Weather:
    """Forecast fields (frames, rows, cols) by key: ce, cn (m/s), hs (m), wdir (deg from), wind
    (m/s); frame k valid first_h + k step_h hours after departure, linear in between, held
    outside. ship: speed loss 'khokhlov' or 'none', displacement_t, max_wind_ms, max_wave_m."""

    def __init__(
        self,
        fields,
        lat,
        lon,
        *,
        first_h=0.0,
        step_h=6.0,
        displacement_t=15000.0,
        khokhlov=True,
        max_wind_ms=25.0,
        max_wave_m=5.0,
    ):
        self.f = {k: np.asarray(v, dtype=np.float64) for k, v in fields.items()}
        self.lat, self.lon = np.asarray(lat, float), np.asarray(lon, float)
        self.first_h, self.step_h = first_h, step_h
        self.d, self.khokhlov = displacement_t, khokhlov
        self.max_wind, self.max_wave = max_wind_ms, max_wave_m
        self.frames = next(iter(self.f.values())).shape[0] if self.f else 1

    def at(self, key, t, rc):
        x = min(max((t - self.first_h) / self.step_h, 0.0), self.frames - 1)
        i0 = int(math.floor(x))
        i1, a = min(i0 + 1, self.frames - 1), x - i0
        v = self.f[key]
        return (1 - a) * v[i0, rc[0], rc[1]] + a * v[i1, rc[0], rc[1]]

    def course(self, p, q):
        p1, p2 = math.radians(self.lat[p[0]]), math.radians(self.lat[q[0]])
        dl = math.radians(self.lon[q[1]] - self.lon[p[1]])
        return math.atan2(
            math.sin(dl) * math.cos(p2),
            math.cos(p1) * math.sin(p2) - math.sin(p1) * math.cos(p2) * math.cos(dl),
        )

    def speed(self, p, q, t, v0):
        """Speed over ground (kn) on the step p -> q started at t, from the speed v0 through
        calm water; 0 where the wind or waves close it or the track cannot be held."""
        if "wind" in self.f and max(self.at("wind", t, p), self.at("wind", t, q)) > self.max_wind:
            return 0.0
        course, v = self.course(p, q), v0
        if "hs" in self.f:
            hp, hq = self.at("hs", t, p), self.at("hs", t, q)
            if max(hp, hq) > self.max_wave:
                return 0.0
            if self.khokhlov:
                bearing = 0.0
                if "wdir" in self.f:
                    a, b = math.radians(self.at("wdir", t, p)), math.radians(self.at("wdir", t, q))
                    frm = math.atan2(math.sin(a) + math.sin(b), math.cos(a) + math.cos(b))
                    bearing = abs(math.remainder(frm - course, 2 * math.pi))
                h3 = 1.32 * 0.5 * (hp + hq)
                v = v - (0.745 * h3 - 0.275 * bearing * h3) * (1 - 1.35e-6 * self.d * v)
        if "ce" in self.f:
            ce = 0.5 * (self.at("ce", t, p) + self.at("ce", t, q)) * KNOTS_PER_MS
            cn = 0.5 * (self.at("cn", t, p) + self.at("cn", t, q)) * KNOTS_PER_MS
            vt = math.hypot(ce, cn)
            if vt > 0:
                ang = math.atan2(ce, cn) - course
                along, cross = vt * math.cos(ang), vt * math.sin(ang)
                if abs(cross) >= v:
                    return 0.0
                v = along + math.sqrt(v * v - cross * cross)
        return v if v > 1e-9 else 0.0


def ice_weather_step_arrival(hours_per_km, valid_from_h, weather, p, q, t):
    """Earliest arrival at q for a ship at p at time t: it leaves at t or at a later chart's
    time d; the ice of the chart valid at d gives the time through calm water (length x the
    pieces' hours per km; closed if a touched pixel is inf), whose speed the weather at d
    changes; the step takes length / speed over ground."""
    di, dj = q[0] - p[0], q[1] - p[1]
    length = float(haversine(weather.lat[p[0]], weather.lon[p[1]], weather.lat[q[0]], weather.lon[q[1]]))
    best = math.inf
    for d in [t] + [float(x) for x in valid_from_h if x > t]:
        k = max([i for i, x in enumerate(valid_from_h) if x <= d] or [0])
        h = hours_per_km[k]
        if any(not np.isfinite(h[p[0] + a, p[1] + b]) for a, b in touched(di, dj)):
            continue
        ice_h = length * sum(f * float(h[p[0] + a, p[1] + b]) for (a, b), f in pieces(di, dj))
        sog = weather.speed(p, q, d, length / KM_PER_NM / ice_h)
        if sog > 0:
            best = min(best, d + length / KM_PER_NM / sog)
    return best


def ice_weather_best_arrival(hours_per_km, valid_from_h, weather, start, end, k=3):
    """The earliest arrival through ice and weather over every simple path
    (support.reference.best_arrival_over_paths)."""
    return best_arrival_over_paths(
        hours_per_km.shape[1:],
        start,
        end,
        k,
        lambda p, q, t: ice_weather_step_arrival(hours_per_km, valid_from_h, weather, p, q, t),
    )
