"""Great-circle corridors: the graph of Olovyannikov 2025 and Grinyak et al. 2018 as a grid on the same engine.

Layers are spaced evenly along the great circle start -> end (spacing in nautical miles, or in
hours of steaming at a speed: Olovyannikov 2025 uses 12 h = 120 nm); each layer holds 2m + 1 nodes on
the great circle through its centre perpendicular to the track, `row_nm` apart (Olovyannikov 2025:
20 nm). Node (j, i) is row j (j = m on the track) of layer i. The environment is sampled at the
nodes (and, to forbid an edge that crosses land, at `checks` points along each edge).

Two graphs:
* steps="forward" (Olovyannikov 2025 and Grinyak et al. 2018): edges only from layer i to layer i + 1, to any row within
  `max_shift` rows; solved exactly by dynamic programming in Python with the true great-circle
  length of every edge.
* steps="stencil": the k x k stencil of the C++ engine on the (row, layer) grid taken as a planar
  chart with dx = the layer spacing and dy = the row spacing. Off-track rows are longer or
  shorter than the layer spacing (rows converge and diverge), so the engine's step lengths are
  approximate; the route it picks is then re-costed with exact great-circle lengths, and
  stats.corridor.planar_length_error gives the largest relative error of the engine's step
  lengths on that route (~(row offset / R)^2 and the track's curvature: below 1 % for corridors
  a few hundred nm wide); stats.corridor.planar_cost is the engine's cost on the planar grid.
Edge cost: edge_cost="max": max(u_a, u_b) x km; "mean": (u_a + u_b)/2 x km (Grinyak et al. 2022 and Grinyak et al. 2018),
priced by the engine's models (seaway.models.EdgeCost.pair_costs)."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from .base import sphere as geo
from .base.validate import number
from .chart.raster import as_chart
from .engine.api import route as engine_route
from .errors import NoRouteError, SeawayError
from .models.base import EdgeCost
from .result.route import Route
from .result.stats import CorridorStencil, RouteStats


@dataclass
class Corridor:
    start: tuple
    end: tuple
    lat: np.ndarray  # (2m + 1, layers) node latitudes
    lon: np.ndarray  # node longitudes in [-180, 180)
    leg_km: float
    row_km: float
    distance_km: float

    @property
    def shape(self):
        """(rows, layers) of the corridor's grid."""
        return self.lat.shape

    @property
    def m(self) -> int:
        """Rows on each side of the great circle."""
        return self.lat.shape[0] // 2

    @property
    def track(self) -> np.ndarray:
        """(layers, 2) lat/lon of the great circle's nodes (row m)."""
        return np.column_stack([self.lat[self.m], self.lon[self.m]])

    def sample(self, env, lat=None, lon=None) -> np.ndarray:
        """`env` at (lat, lon) (default: the nodes): a callable f(lat, lon), a number, or an
        xarray.DataArray on lat/lon (nearest pixel; NaN outside the chart)."""
        lat = self.lat if lat is None else lat
        lon = self.lon if lon is None else lon
        if env is None:
            return np.ones(np.shape(lat))
        if callable(env):
            return np.asarray(env(lat, lon), float) * np.ones(np.shape(lat))
        if np.isscalar(env):
            return np.full(np.shape(lat), float(env))
        import xarray as xr

        la, lo = _names(env)
        glon = np.asarray(lon, float)
        glon = glon % 360.0 if float(env[lo].max()) > 180 else geo.wrap_lon(glon)
        pts = {la: xr.DataArray(np.ravel(lat), dims="p"), lo: xr.DataArray(np.ravel(glon), dims="p")}
        out = env.sel(pts, method="nearest").values.astype(float)
        inside = _inside(env[la].values, np.ravel(lat)) & _inside(env[lo].values, np.ravel(glon))
        return np.where(inside, out, np.nan).reshape(np.shape(lat))

    def route(
        self,
        env=None,
        *,
        steps="forward",
        max_shift=None,
        neighbourhood=5,
        edge_cost="max",
        checks=8,
        speed_kn=None,
    ) -> Route:
        """The least-cost route along the corridor from the start to the end node."""
        if edge_cost not in ("max", "mean"):
            raise SeawayError(f"edge_cost must be 'max' or 'mean' on a corridor, got {edge_cost!r}")
        model = EdgeCost(edge_cost)
        u = self.sample(env)
        u = np.where(np.isfinite(u) & (u >= 0), u, np.inf)
        rows, layers = u.shape
        if steps == "forward":
            path = self._forward(u, env, max_shift or rows, model, checks)
            stats = RouteStats()  # dynamic programming: no search figures
        elif steps == "stencil":
            r = engine_route(
                u,
                (self.m, 0),
                (self.m, layers - 1),
                dx=self.leg_km,
                dy=self.row_km,
                neighbourhood=neighbourhood,
                edge_cost=edge_cost,
            )
            path, stats = r.pixels, r.stats
        else:
            raise SeawayError(f"steps must be 'forward' or 'stencil', got {steps!r}")
        chart = as_chart(u, dx=self.leg_km, dy=self.row_km)
        ll = np.column_stack([self.lat[path[:, 0], path[:, 1]], self.lon[path[:, 0], path[:, 1]]])
        km = geo.distance_km(ll[:-1, 0], ll[:-1, 1], ll[1:, 0], ll[1:, 1])
        costs = model.pair_costs(u[path[:-1, 0], path[:-1, 1]], u[path[1:, 0], path[1:, 1]], km)
        if steps == "stencil":
            d = np.diff(path, axis=0)
            planar = np.hypot(d[:, 0] * self.row_km, d[:, 1] * self.leg_km)
            error = float(np.max(np.abs(planar / km - 1))) if len(km) else 0.0
            stats = dataclasses.replace(stats, corridor=CorridorStencil(r.cost, error))
        return Route(
            chart=chart,
            cost=float(costs.sum()),
            pixels=path,
            method=f"corridor-{steps}",
            neighbourhood=neighbourhood,
            model=model,
            stats=stats,
            latlon=ll,
            step_costs=costs,
            speed_kn=speed_kn,
            name="great-circle corridor route",
        )

    def _forward(self, u, env, max_shift, model, checks):
        rows, layers = u.shape
        best = np.full(rows, np.inf)
        best[self.m] = 0.0
        back = np.zeros((rows, layers), np.int64)
        j = np.arange(rows)
        a, b = np.meshgrid(j, j, indexing="ij")  # from row a to row b
        for i in range(layers - 1):
            la0, lo0 = self.lat[a, i], self.lon[a, i]
            la1, lo1 = self.lat[b, i + 1], self.lon[b, i + 1]
            km = geo.distance_km(la0, lo0, la1, lo1)
            w = model.pair_costs(u[a, i].ravel(), u[b, i + 1].ravel(), km.ravel()).reshape(km.shape)
            w[np.abs(a - b) > max_shift] = np.inf
            if checks and env is not None:
                w[self._blocked(env, la0, lo0, la1, lo1, checks)] = np.inf
            total = best[:, None] + w
            back[:, i + 1] = np.argmin(total, axis=0)
            best = total[back[:, i + 1], j]
        if not np.isfinite(best[self.m]):
            raise NoRouteError(
                "no route along the corridor: every chain of edges meets impassable "
                "water; widen the corridor (more rows) or allow larger shifts"
            )
        path = [self.m]
        for i in range(layers - 1, 0, -1):
            path.append(back[path[-1], i])
        return np.column_stack([path[::-1], np.arange(layers)]).astype(np.int64)

    def _blocked(self, env, la0, lo0, la1, lo1, checks):
        """Edges along which one of `checks` interior points is impassable."""
        bad = np.zeros(la0.shape, bool)
        for t in (np.arange(checks) + 1) / (checks + 1):
            # points along each edge: linear in lat/lon over ~120 nm, well within a node spacing
            dlo = (lo1 - lo0 + 180) % 360 - 180
            v = self.sample(env, la0 + t * (la1 - la0), lo0 + t * dlo)
            bad |= ~(np.isfinite(v) & (v >= 0))
        return bad


def corridor(start, end, *, spacing_nm=None, hours=None, speed_kn=None, row_nm=20.0, m=10):
    """The corridor around the great circle start -> end ((lat, lon) in degrees).

    Layer spacing: spacing_nm, or hours x speed_kn (Olovyannikov 2025: 12 h at 10 kn = 120 nm); the
    number of legs is round(distance / spacing) (at least 1), so the legs are equal and within
    half a spacing of the one asked for. row_nm apart across the track, m rows on each side."""
    if spacing_nm is None:
        if hours is None or speed_kn is None:
            raise SeawayError("give spacing_nm, or hours and speed_kn")
        spacing_nm = number(hours, "hours", above=0) * number(speed_kn, "speed_kn", above=0)
    number(spacing_nm, "spacing_nm", above=0)
    number(row_nm, "row_nm", above=0)
    number(m, "m", minimum=0, integer=True)
    (lat1, lon1), (lat2, lon2) = start, end
    dist = float(geo.distance_km(lat1, lon1, lat2, lon2))
    legs = max(int(round(dist / (spacing_nm * geo.KM_PER_NM))), 1)
    tlat, tlon = geo.intermediate(lat1, lon1, lat2, lon2, np.linspace(0, 1, legs + 1))
    nxt = np.roll(np.column_stack([tlat, tlon]), -1, axis=0)
    course = geo.course_deg(tlat, tlon, nxt[:, 0], nxt[:, 1])
    course[-1] = (geo.course_deg(tlat[-1], tlon[-1], tlat[-2], tlon[-2]) + 180) % 360
    offsets = (np.arange(2 * int(m) + 1) - int(m)) * row_nm * geo.KM_PER_NM
    side = np.where(offsets[:, None] >= 0, course[None, :] + 90, course[None, :] - 90)
    lat, lon = geo.destination(tlat[None, :], tlon[None, :], side, np.abs(offsets)[:, None])
    return Corridor(
        start=(lat1, lon1),
        end=(lat2, lon2),
        lat=lat,
        lon=lon,
        leg_km=dist / legs,
        row_km=row_nm * geo.KM_PER_NM,
        distance_km=dist,
    )


def _names(da):
    la = next((n for n in ("lat", "latitude") if n in da.coords), None)
    lo = next((n for n in ("lon", "longitude") if n in da.coords), None)
    if la is None or lo is None:
        raise SeawayError(
            "the environment must be a DataArray with lat/lon coordinates, a number or a function f(lat, lon)"
        )
    return la, lo


def _inside(axis, v):
    step = abs(axis[1] - axis[0]) / 2 if len(axis) > 1 else 0.5
    return (v >= axis.min() - step) & (v <= axis.max() + step)
