"""Reference for seaway._segments: the numpy leg model seaway used before the C++ one
(cpp/seaway/legs.hpp), kept as an independent check of it (tests/test_smooth.py).

The cost and land test of an arbitrary straight leg on a chart, consistent with the engine.

Points are fractional (row, col) pixel indices; pixel (i, j) is the closed square
[i - 1/2, i + 1/2] x [j - 1/2, j + 1/2]. A leg is forbidden when the closed path touches the
closed square of an impassable pixel or leaves the chart (the engine's land rule).

Path of a leg: on planar charts the straight segment; on geographic charts the great circle
between its ends, followed through lat/lon index space as a polyline with one vertex every
<= 4 pixels (the chord of a 4-pixel piece departs from the arc by ~1e-3 pixel). A leg that is
one of the engine's stencil steps (pixel centres, offset within the k x k square) is the
engine's straight segment in index space, so it costs exactly what the engine charges.

Cost of a leg: split the path at pixel boundaries into pieces of lengths l_k (great-circle km or
planar units) inside pixels of cost u_k.
* "integral": sum l_k u_k (the engine's exact line integral).
* "max" / "mean": the engine's edge rule applied to the chain of pixels the leg crosses: the
  move between consecutive pixels k, k+1 has length (l_k + l_(k+1))/2 (the first and last
  half-pieces go to the first and last move) and costs max(u_k, u_(k+1)) or their mean per unit
  length; a leg inside one pixel costs l_0 u_0. A stencil step of the engine costs what the
  engine charges (max(u_i, u_j) r or (u_i + u_j)/2 r: only its two ends count).
A piece lying exactly on a pixel boundary is charged the larger of the two sides."""

from __future__ import annotations

import numpy as np

from seaway.base import sphere as geo

EPS = 1e-9
SUBDIVIDE = 4.0  # index-space length of the pieces a great-circle leg is followed by


class Segments:
    def __init__(self, chart, edge_cost: str = "integral", neighbourhood: int = 3):
        self.chart, self.edge_cost, self.half = chart, edge_cost, (neighbourhood - 1) // 2
        u = np.array(chart.values, dtype=np.float64)
        u[~np.isfinite(u)] = np.inf
        if chart.land is not None:
            u[chart.land != 0] = np.inf
        self.u = u
        self.rows, self.cols = u.shape
        g = chart.grid
        self.geographic, self.wrap = chart.geographic, bool(chart.geographic and g.wrap)
        if self.geographic:
            self.lat0, self.dlat, self.lon0, self.dlon = g.lat0, g.dlat, g.lon0, g.dlon
        else:
            self.dy, self.dx = g.dy, g.dx

    # -- coordinates -------------------------------------------------------------------------
    def _path(self, p, q, straight: bool) -> np.ndarray:
        """Vertices of the leg's path in index space."""
        n_index = float(np.hypot(*(q - p)))
        if not self.geographic or straight or n_index <= SUBDIVIDE:
            return np.array([p, q])
        lat1, lon1 = self.lat0 + p[0] * self.dlat, self.lon0 + p[1] * self.dlon
        lat2, lon2 = self.lat0 + q[0] * self.dlat, self.lon0 + q[1] * self.dlon
        m = int(np.ceil(n_index / SUBDIVIDE))
        lat, lon = geo.intermediate(lat1, lon1, lat2, lon2, np.linspace(0.0, 1.0, m + 1))
        lon = geo.unwrap_lon(np.concatenate([[lon1], lon]))[1:]
        lon += lon1 - lon[0]
        path = np.column_stack([(lat - self.lat0) / self.dlat, (lon - self.lon0) / self.dlon])
        last = np.array(q, float)
        if self.wrap:  # a leg across the seam ends at q's column + a whole turn
            last[1] += self.cols * np.round((path[-1, 1] - q[1]) / self.cols)
        path[0], path[-1] = p, last
        return path

    # -- pixels ------------------------------------------------------------------------------
    def _candidates(self, pts):
        """Every pixel whose closed square holds one of `pts`: (rows, cols) arrays."""
        lo, hi = np.floor(pts + 0.5 - EPS).astype(np.int64), np.floor(pts + 0.5 + EPS).astype(np.int64)
        r = np.concatenate([lo[:, 0], lo[:, 0], hi[:, 0], hi[:, 0]])
        c = np.concatenate([lo[:, 1], hi[:, 1], lo[:, 1], hi[:, 1]])
        return r, c

    def _u_at(self, r, c) -> np.ndarray:
        """Cost of pixels (inf outside the chart); columns wrap on a 360-degree chart."""
        if self.wrap:
            c = c % self.cols
        inside = (r >= 0) & (r < self.rows) & (c >= 0) & (c < self.cols)
        out = np.full(r.shape, np.inf)
        out[inside] = self.u[r[inside], c[inside]]
        return out

    def _pieces(self, path):
        """Pieces of the polyline `path` inside single pixels: (lengths, pixel costs, pixel ids),
        or None if the closed polyline touches an impassable pixel or leaves the chart."""
        a, b = path[:-1], path[1:]
        m = len(a)
        segs, ts = [np.arange(m), np.arange(m)], [np.zeros(m), np.ones(m)]
        for axis in (0, 1):
            lo, hi = np.minimum(a[:, axis], b[:, axis]), np.maximum(a[:, axis], b[:, axis])
            k0, k1 = np.ceil(lo - 0.5 - EPS), np.floor(hi - 0.5 + EPS)
            n = np.where(hi - lo > EPS, np.maximum(k1 - k0 + 1, 0), 0).astype(np.int64)
            s = np.repeat(np.arange(m), n)
            k = k0[s] + np.arange(n.sum()) - np.repeat(np.cumsum(n) - n, n) + 0.5
            segs.append(s)
            ts.append(np.clip((k - a[s, axis]) / (b[s, axis] - a[s, axis]), 0.0, 1.0))
        s, t = np.concatenate(segs), np.concatenate(ts)
        order = np.lexsort((t, s))
        s, t = s[order], t[order]
        keep = np.ones(len(t), bool)
        keep[1:] = (s[1:] != s[:-1]) | (t[1:] - t[:-1] > EPS)
        s, t = s[keep], t[keep]
        same = s[1:] == s[:-1]
        t0, t1, ps = t[:-1][same], t[1:][same], s[:-1][same]
        d = b - a
        mids = a[ps] + ((t0 + t1) / 2)[:, None] * d[ps]
        pts = np.concatenate([a[s] + t[:, None] * d[s], mids])
        if not np.all(np.isfinite(self._u_at(*self._candidates(pts)))):
            return None
        r, c = self._candidates(mids)
        n = len(mids)
        u = self._u_at(r, c).reshape(4, -1).max(axis=0)
        return (t1 - t0) * self._lengths(a, b)[ps], u, r[:n] * (self.cols + 1) + c[:n]

    def _lengths(self, a, b) -> np.ndarray:
        if self.geographic:
            return geo.distance_km(
                self.lat0 + a[:, 0] * self.dlat,
                self.lon0 + a[:, 1] * self.dlon,
                self.lat0 + b[:, 0] * self.dlat,
                self.lon0 + b[:, 1] * self.dlon,
            )
        return np.hypot((b[:, 0] - a[:, 0]) * self.dy, (b[:, 1] - a[:, 1]) * self.dx)

    # -- legs --------------------------------------------------------------------------------
    def is_step(self, p, q) -> bool:
        d = np.abs(q - p)
        return bool(np.all(p == np.round(p)) and np.all(q == np.round(q)) and d.max() <= self.half)

    def leg(self, p, q) -> tuple[float, float]:
        """(cost, length) of the leg p -> q; (inf, length) if it is forbidden."""
        p, q = np.asarray(p, float), np.asarray(q, float)
        step = self.is_step(p, q)
        path = self._path(p, q, straight=step)
        got = self._pieces(path)
        if got is None:
            return np.inf, float(self._lengths(path[:-1], path[1:]).sum())
        ell, u, pid = got
        total = float(ell.sum())
        if self.edge_cost == "integral":
            return float(ell @ u), total
        if self.edge_cost == "length":
            return total, total
        if step:
            ue = self._u_at(np.array([p[0], q[0]], np.int64), np.array([p[1], q[1]], np.int64))
            f = max(ue) if self.edge_cost == "max" else (ue[0] + ue[1]) / 2
            return float(f * total), total
        keep = np.concatenate([[True], pid[1:] != pid[:-1]])  # one piece per pixel crossed
        idx = np.cumsum(keep) - 1
        ell, u = np.bincount(idx, ell), u[keep]
        if len(u) == 1:
            return float(ell[0] * u[0]), total
        move = (ell[:-1] + ell[1:]) / 2
        move[0] += ell[0] / 2
        move[-1] += ell[-1] / 2
        f = np.maximum(u[:-1], u[1:]) if self.edge_cost == "max" else (u[:-1] + u[1:]) / 2
        return float(move @ f), total

    def cost(self, pts) -> float:
        return float(sum(self.leg(a, b)[0] for a, b in zip(pts[:-1], pts[1:])))
