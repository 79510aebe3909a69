"""Weather routing (papers 001, 004): formulas, currents, storms in time, brute force."""

import functools
import itertools

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway import _core
from seaway.weather import KNOTS_PER_MS, Vessel, rhumb_line_km, route_time
from support.data import SHARED_DATA
from support.forecasts import forecast

#: The engine's steps: these tests hold them to brute force and to values by hand.
route_time = functools.partial(route_time, smooth=False)

CALM = Vessel(speed_kn=12.0, speed_loss="none")


def test_paper_001_formulas_by_hand():
    # Khokhlov, 15 000 t at 15 kn in 3 m significant waves: h3 = 1.32 x 3 = 3.96 m,
    # (1 - 1.35e-6 x 15000 x 15) = 0.69625. Head seas: loss 0.745 x 3.96 x 0.69625 = 2.05408 kn.
    assert _core.khokhlov_speed_kn(15, 3.96, 0.0, 15000) == pytest.approx(12.94592, abs=1e-5)
    # Following seas (q = pi): (0.745 - 0.275 pi) x 3.96 x 0.69625 = -0.32793: a small gain.
    assert _core.khokhlov_speed_kn(15, 3.96, np.pi, 15000) == pytest.approx(15.32793, abs=1e-5)
    # Current 2 kn against a 12 kn ship: along the course 14, against 10, across sqrt(140).
    assert _core.speed_over_ground_kn(12, 2, 0.0) == pytest.approx(14.0)
    assert _core.speed_over_ground_kn(12, 2, np.pi) == pytest.approx(10.0)
    assert _core.speed_over_ground_kn(12, 2, np.pi / 2) == pytest.approx(np.sqrt(140))
    assert _core.speed_over_ground_kn(12, 13, np.pi / 2) == 0  # the track cannot be held


def test_calm_passage_time_is_distance_over_speed():
    r = route_time(forecast(), (61.0, 0.5), (61.0, 2.5), vessel=CALM, neighbourhood=3)
    # Along one row of the grid: the sum of the step lengths over 12 kn.
    km = sum(_core.haversine_km(61.0, a, 61.0, a + 0.1) for a in np.arange(0.5, 2.5, 0.1))
    assert r.cost == pytest.approx(km / 1.852 / 12.0, rel=1e-9)
    assert r.length == pytest.approx(km, rel=1e-9)


def test_following_current_shortens_and_head_current_lengthens():
    east = forecast(ce=1.0, cn=0.0)  # 1 m/s towards the east = 1.944 kn
    calm = route_time(forecast(), (61.0, 0.5), (61.0, 2.5), vessel=CALM, neighbourhood=3).cost
    with_current = route_time(east, (61.0, 0.5), (61.0, 2.5), vessel=CALM, neighbourhood=3).cost
    against = route_time(east, (61.0, 2.5), (61.0, 0.5), vessel=CALM, neighbourhood=3).cost
    # An east step along a parallel sets off on its great circle 0.04 degrees north of east,
    # so the current is not quite along the track: agreement to 1e-6, not to rounding.
    assert with_current == pytest.approx(calm * 12 / (12 + KNOTS_PER_MS), rel=1e-6)
    assert against == pytest.approx(calm * 12 / (12 - KNOTS_PER_MS), rel=1e-6)


def test_route_bends_into_a_favourable_current():
    ce = np.zeros((21, 31))
    ce[8:10, :] = 3.0  # a 5.8 kn eastward stream 11-22 km south of the straight line
    fc = forecast(ce=ce, cn=0.0)
    r = route_time(fc, (61.0, 0.2), (61.0, 2.8), vessel=CALM, neighbourhood=5)
    calm = route_time(forecast(), (61.0, 0.2), (61.0, 2.8), vessel=CALM, neighbourhood=5)
    assert r.cost < 0.95 * calm.cost
    assert r.coords[:, 0].min() <= 60.9  # it went down into the stream (lat 60.8-60.9)
    assert calm.coords[:, 0].min() == pytest.approx(61.0)


def test_storm_is_avoided_only_while_forecast():
    # Wind 20 m/s over the middle of the straight line for the first 12 h, calm afterwards;
    # danger zones (paper 004) at 11 m/s.
    wind = np.zeros((8, 21, 31))
    wind[:3, 6:15, 10:20] = 20.0  # frames 0, 6, 12 h
    fc = forecast(frames=8, wind=wind, ce=0.0, cn=0.0)
    ship = Vessel(speed_kn=12.0, speed_loss="none", danger_wind_ms=11.0)
    straight = route_time(forecast(), (61.0, 0.2), (61.0, 2.8), vessel=CALM, neighbourhood=5)
    early = route_time(fc, (61.0, 0.2), (61.0, 2.8), vessel=ship, neighbourhood=5)
    late = route_time(fc, (61.0, 0.2), (61.0, 2.8), vessel=ship, neighbourhood=5, departure="2026-01-01T18")
    assert early.cost > straight.cost * 1.02  # a detour around the storm
    inside = [(6 <= r <= 14) and (10 <= c <= 19) for r, c in early.pixels]
    assert not any(inside)
    assert late.cost == pytest.approx(straight.cost, rel=1e-12)
    assert late.stats.voyage.arrival == np.datetime64("2026-01-01T18") + np.timedelta64(
        int(round(late.cost * 3600)), "s"
    )


def _simulate(fc, pixels, ship):
    """Arrival time (h) along a pixel path, stepping the C++ physics' Python twin."""
    lat, lon = fc.lat.values, fc.lon.values
    t = 0.0
    frames = fc.sizes["time"]
    for (r1, c1), (r2, c2) in zip(pixels[:-1], pixels[1:]):
        x = min(max(t / 6.0, 0), frames - 1)
        i0, a = int(x), x - int(x)
        i1 = min(i0 + 1, frames - 1)

        def at(name, r, c):
            v = fc[name].values
            return (1 - a) * v[i0, r, c] + a * v[i1, r, c]

        if max(at("wind", r1, c1), at("wind", r2, c2)) > ship.danger_wind_ms:
            return np.inf
        p1, p2, dl = np.radians(lat[r1]), np.radians(lat[r2]), np.radians(lon[c2] - lon[c1])
        course = np.arctan2(
            np.sin(dl) * np.cos(p2), np.cos(p1) * np.sin(p2) - np.sin(p1) * np.cos(p2) * np.cos(dl)
        )
        ce = 0.5 * (at("ce", r1, c1) + at("ce", r2, c2)) * KNOTS_PER_MS
        cn = 0.5 * (at("cn", r1, c1) + at("cn", r2, c2)) * KNOTS_PER_MS
        vt, q = np.hypot(ce, cn), np.arctan2(ce, cn) - course
        along, cross = vt * np.cos(q), vt * np.sin(q)
        if abs(cross) >= ship.speed_kn:
            return np.inf
        sog = along + np.sqrt(ship.speed_kn**2 - cross**2)
        if sog <= 0:
            return np.inf
        t += _core.haversine_km(lat[r1], lon[c1], lat[r2], lon[c2]) / 1.852 / sog
    return t


@pytest.mark.slow
def test_time_dependent_search_equals_brute_force_over_all_paths():
    rng = np.random.default_rng(7)
    shape, frames = (3, 4), 4
    fc = forecast(
        shape=shape,
        frames=frames,
        step=0.5,
        hours=6,
        ce=rng.uniform(-3, 3, (frames,) + shape),
        cn=rng.uniform(-3, 3, (frames,) + shape),
        wind=rng.uniform(0, 14, (frames,) + shape),
    )
    ship = Vessel(speed_kn=9.0, speed_loss="none", danger_wind_ms=12.0)
    start, end = (0, 0), (2, 3)
    # Every simple path of 8-neighbour steps from start to end, simulated step by step.
    best = np.inf
    cells = [(r, c) for r in range(3) for c in range(4)]
    for n in range(1, len(cells)):
        for middle in itertools.permutations([p for p in cells if p not in (start, end)], n - 1):
            path = [start, *middle, end]
            if all(max(abs(a[0] - b[0]), abs(a[1] - b[1])) == 1 for a, b in zip(path, path[1:])):
                best = min(best, _simulate(fc, path, ship))
    lat, lon = fc.lat.values, fc.lon.values
    for method in ("dijkstra", "astar"):
        try:
            got = route_time(
                fc, (lat[0], lon[0]), (lat[2], lon[3]), vessel=ship, neighbourhood=3, method=method
            ).cost
        except seaway.NoRouteError:
            got = np.inf
        assert got == pytest.approx(best, rel=1e-9)
    assert np.isfinite(best)


def test_paper_004_great_circle_versus_rhumb_line():
    # A(52.5 N, 12.1 W) -> B(8.4 N, 57.9 W): the paper's ratio 6446.4 / 6395.5 = 1.0080.
    gc = _core.haversine_km(52.5, -12.1, 8.4, -57.9)
    rl = rhumb_line_km(52.5, -12.1, 8.4, -57.9)
    assert rl / gc == pytest.approx(1.0080, abs=1e-4)
    assert gc == pytest.approx(6405, abs=1) and rl == pytest.approx(6457, abs=1)  # R = 6371 km


def test_khokhlov_outside_its_range_is_refused_or_warned():
    with pytest.raises(ValueError, match="speed_loss='stawave1' covers other ships"):
        route_time(forecast(hs=1.0), (61.0, 0.5), (61.0, 2.5), vessel=Vessel(displacement_t=40000))
    with pytest.warns(UserWarning, match="5000-25000 t"):
        route_time(
            forecast(hs=1.0),
            (61.0, 0.5),
            (61.0, 2.5),
            vessel=Vessel(displacement_t=40000, outside_validity="warn"),
        )


def test_waves_above_the_limit_are_impassable():
    hs = np.full((21, 31), 2.0)
    hs[:, 14:17] = 6.0  # a wall of 6 m waves across the chart
    with pytest.raises(seaway.NoRouteError, match="wind and wave limits"):
        route_time(forecast(hs=hs, wdir=270.0), (61.0, 0.5), (61.0, 2.5), vessel=Vessel())


ROMS = SHARED_DATA / "ocean_model" / "metno_ROMS_Arctic20_1to5Feb_2016.nc"


def test_to_latlon_turns_grid_vectors_to_east_and_north():
    pyproj = pytest.importorskip("pyproj")
    from seaway.weather.forecast import to_latlon

    # ROMS Arctic's projection; a current of 1 m/s due north everywhere, given in grid x/y:
    # on a north-polar stereographic grid north is (-sin t, cos t), t = lon - lon_0.
    crs = "+proj=stere +a=6371000 +b=6371000 +lat_0=90 +lat_ts=60 +lon_0=58"
    X, Y = np.arange(-2000.0, -100.0, 20.0), np.arange(-1800.0, -700.0, 20.0)
    xx, yy = np.meshgrid(X, Y)
    lon, _ = pyproj.Transformer.from_crs(crs, "EPSG:4326", always_xy=True).transform(xx * 1e3, yy * 1e3)
    t = np.radians(lon - 58.0)
    ds = xr.Dataset(
        {
            "u": (("Y", "X"), -np.sin(t), {"standard_name": "x_sea_water_velocity", "grid_mapping": "gm"}),
            "v": (("Y", "X"), np.cos(t), {"standard_name": "y_sea_water_velocity", "grid_mapping": "gm"}),
            "gm": ((), 0, {"proj4_string": crs}),
        },
        coords={
            "X": ("X", X, {"standard_name": "projection_x_coordinate", "units": "km"}),
            "Y": ("Y", Y, {"standard_name": "projection_y_coordinate", "units": "km"}),
        },
    )
    out = to_latlon(ds, np.arange(70.0, 76.0, 0.5), np.arange(10.0, 40.0, 1.0))
    assert out["u"].attrs["standard_name"] == "eastward_sea_water_velocity"
    u, v = out["u"].values, out["v"].values
    inside = np.isfinite(u)  # NaN where the lat/lon point falls outside the model grid
    assert inside.mean() > 0.5
    assert np.abs(u[inside]).max() < 2e-3  # bilinear error of a smooth field
    assert np.abs(v[inside] - 1.0).max() < 2e-3


@pytest.mark.needs_data(ROMS)
def test_route_on_the_roms_currents():
    from seaway.weather.forecast import read_forecast, to_latlon

    pytest.importorskip("pyproj")
    ds = read_forecast(ROMS)[["ubar", "vbar", "mask", "polar_stereographic"]]
    lat, lon = np.arange(70.0, 78.01, 0.1), np.arange(15.0, 50.01, 0.25)
    fc = to_latlon(ds, lat, lon)
    ue = fc["ubar"].isel(time=0).values
    assert fc["ubar"].attrs["standard_name"] == "barotropic_eastward_sea_water_velocity"
    land = (fc["mask"].isel(time=0, drop=True) < 0.5) if "time" in fc["mask"].dims else fc["mask"] < 0.5
    fc = fc.drop_vars("mask")
    start, end = (71.0, 20.0), (76.0, 45.0)  # off northern Norway -> towards Novaya Zemlya, at sea
    ship = Vessel(speed_kn=12.0, speed_loss="none")
    r = route_time(fc, start, end, vessel=ship, land=land.values | np.isnan(ue), neighbourhood=5)
    back = route_time(fc, end, start, vessel=ship, land=land.values | np.isnan(ue), neighbourhood=5)
    gc_h = _core.haversine_km(*start, *end) / 1.852 / 12.0
    # Currents of a few tenths of a knot change a ~1000 km passage by a few per cent at most.
    assert gc_h < r.cost < 1.1 * gc_h and gc_h < back.cost < 1.1 * gc_h
    assert r.cost != pytest.approx(back.cost, rel=1e-6)  # the currents make the two differ
    assert r.stats.voyage.departure == ds["time"].values[0]


def test_replanning_with_the_same_forecast_keeps_the_tail():
    rng = np.random.default_rng(3)
    fc = forecast(frames=6, ce=rng.uniform(-1, 1, (6, 21, 31)), cn=rng.uniform(-1, 1, (6, 21, 31)))
    from seaway.weather import position_at, replan

    r = route_time(fc, (60.2, 0.2), (61.8, 2.8), vessel=CALM, neighbourhood=5)
    i, here = position_at(r, 3.0)
    assert 0 < i < len(r.pixels) - 1 and np.sum(r.costs()[:i]) <= 3.0 < np.sum(r.costs()[: i + 1])
    again = replan(r, 3.0, fc, (61.8, 2.8), vessel=CALM, neighbourhood=5, smooth=False)
    # The tail of a time-optimal route is optimal from the same pixel at the same time (FIFO).
    assert np.sum(r.costs()[:i]) + again.cost == pytest.approx(r.cost, rel=1e-9)
    # A newer forecast with a storm on the old tail changes the rest of the route.
    wind = np.zeros((6, 21, 31))
    rows, cols = zip(*r.pixels[i + 2 : -2])
    wind[:, list(rows), list(cols)] = 30.0
    stormy = forecast(frames=6, wind=wind, ce=fc["ce"].values, cn=fc["cn"].values)
    detour = replan(r, 3.0, stormy, (61.8, 2.8), vessel=CALM, neighbourhood=5, smooth=False)
    assert detour.cost > again.cost


def test_wave_danger_follows_the_circular_criteria():
    L = 100.0  # ship length, m: successive high waves when lambda > 80 m and Hs > 4 m
    pi = np.pi
    assert _core.wave_danger(5.0, 100.0, pi, L, 5.0) == 10.0  # following seas, long high waves
    assert _core.wave_danger(5.0, 100.0, 0.0, L, 5.0) == 1.0  # head seas: not these criteria
    assert _core.wave_danger(5.0, 100.0, np.radians(140), L, 5.0) == 10.0  # quartering, inside
    assert _core.wave_danger(5.0, 100.0, np.radians(100), L, 5.0) == 1.0  # beam seas
    assert _core.wave_danger(5.0, 100.0, np.radians(130), L, 5.0) == pytest.approx(5.5)  # sector edge
    assert _core.wave_danger(5.0, 72.0, pi, L, 5.0) == pytest.approx(5.5)  # lambda / 0.8 L = 0.9
    assert _core.wave_danger(1.0, 100.0, pi, L, 5.0) == 1.0  # low waves
    # Surf-riding: V > 1.8 sqrt(L) / cos(180 - alpha) = 18 kn in following seas.
    assert _core.wave_danger(1.0, 100.0, pi, L, 18.0) == pytest.approx(10.0)
    assert _core.wave_danger(1.0, 100.0, pi, L, 16.2) == pytest.approx(5.5)


def test_safest_route_keeps_out_of_following_seas():
    from seaway.weather import route_safest

    shape = (21, 41)
    period = np.sqrt(100.0 * 2 * np.pi / 9.80665)  # 100 m waves
    waves = forecast(shape=shape, lat0=-1.0, step=0.1, hs=5.0, wdir=270.0, ce=0.0, cn=0.0)
    waves["tp"] = xr.full_like(waves["hs"], period).assign_attrs(standard_name="sea_surface_wave_mean_period")
    east = route_safest(waves, (0.0, 0.2), (0.0, 3.8), ship_length_m=100.0, speed_kn=12.0, neighbourhood=5)
    west = route_safest(waves, (0.0, 3.8), (0.0, 0.2), ship_length_m=100.0, speed_kn=12.0, neighbourhood=5)
    # Into the waves (head seas) the straight line is safe: cost = length (u = 1).
    assert west.cost == pytest.approx(west.length, rel=1e-9)
    assert west.length == pytest.approx(_core.haversine_km(0.0, 0.2, 0.0, 3.8), rel=1e-6)
    # With the waves, every step heads at least 55 degrees off the following-sea bearing (090),
    # so the danger stays 1 and the route tacks: longer, but far cheaper than running before it.
    assert east.cost == pytest.approx(east.length, rel=1e-9)
    d = np.diff(east.pixels, axis=0)
    off = np.degrees(np.abs(np.arctan2(-d[:, 0], d[:, 1])))  # angle from due east
    assert off.min() >= 55.0
    assert east.cost < 10 * west.cost and east.length > 1.5 * west.length


def test_safest_route_names_missing_wave_fields():
    from seaway.weather import route_safest

    with pytest.raises(ValueError, match="sea_surface_wave_mean_period"):
        route_safest(forecast(hs=2.0, wdir=0.0), (61.0, 0.5), (61.0, 2.5), ship_length_m=100, speed_kn=12)


def test_stawave1_speed_loss_by_hand_and_on_a_route():
    # B = 32 m, L = 200 m, Hs = 2 m: R_aw = 1025 x 9.80665 x 4 x 32 x sqrt(0.16) / 16 = 32.166 kN.
    # Calm resistance 500 kN at 14 kn, constant power: x^3 + (32.166 / 500) x - 1 = 0.
    a = 1025 * 9.80665 * 4 * 32 * 0.4 / 16 / 1000 / 500
    roots = np.roots([1, 0, a, -1])
    x = float(roots[np.isreal(roots)].real[0])
    assert x == pytest.approx(0.97856, abs=1e-5)  # 0.97856^3 + 0.064332 x 0.97856 = 1.00000
    assert _core.stawave1_speed_kn(14, 2.0, 32, 200, 500) == pytest.approx(14 * x, rel=1e-12)
    # A large ship outside Khokhlov's range, heading into 2 m head seas (waves from the east).
    ship = Vessel(
        speed_kn=14.0,
        displacement_t=90000,
        speed_loss="stawave1",
        beam_m=32,
        length_m=200,
        calm_resistance_kn=500,
    )
    calm = route_time(forecast(), (61.0, 0.5), (61.0, 2.5), vessel=CALM, neighbourhood=3).cost
    head = route_time(
        forecast(hs=2.0, wdir=90.0), (61.0, 0.5), (61.0, 2.5), vessel=ship, neighbourhood=3
    ).cost
    follow = route_time(
        forecast(hs=2.0, wdir=270.0), (61.0, 0.5), (61.0, 2.5), vessel=ship, neighbourhood=3
    ).cost
    assert head == pytest.approx(calm * 12 / (14 * x), rel=1e-6)  # CALM sails at 12 kn
    assert follow == pytest.approx(calm * 12 / 14, rel=1e-9)  # no added resistance from astern
    with pytest.raises(ValueError, match="2.25 sqrt"):  # 2.25 sqrt(2) = 3.18 m
        route_time(forecast(hs=4.0, wdir=90.0), (61.0, 0.5), (61.0, 2.5), vessel=ship)
    with pytest.raises(ValueError, match="beam_m, length_m and calm_resistance_kn"):
        route_time(forecast(), (61.0, 0.5), (61.0, 2.5), vessel=Vessel(speed_loss="stawave1"))
