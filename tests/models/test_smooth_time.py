"""Smoothing routes on a clock (seaway.smoothtime): never later, never through land or a pixel
closed when the ship is there (every leg sailed again by the dense-sampling reference,
support.reference_timed), waits and via points kept; by hand through ice that opens at a known
time and a zone that opens; the least-danger route left as found, said; fewer legs on the
issue's Kara Sea voyage."""

from __future__ import annotations

import math

import numpy as np
import pytest

from seaway import _core
from seaway.base.units import KM_PER_NM
from seaway.cli import main
from seaway.constraints import Zone, rasterise_zone
from seaway.icenav.season import route_season
from seaway.weather import Vessel, route_time
from support import timed_cases as cases
from support.forecasts import forecast
from support.seasons import planar_season

CASES = {
    "ice planar": cases.ice_planar,
    "ice lat/lon": cases.ice_latlon,
    "weather": cases.weather,
    "ice and weather": cases.ice_weather,
}
CALM = Vessel(speed_kn=12.0, speed_loss="none")


def _kept(raw, smooth):
    """Indices into the raw route's vertices of the smoothed route's, in order."""
    out, i = [], 0
    for p in smooth.pixels:
        while not np.array_equal(raw.pixels[i], p):
            i += 1
        out.append(i)
    return np.array(out)


@pytest.mark.parametrize("kind", CASES)
@pytest.mark.parametrize(
    "seed, smooth", [(1, False), (2, False), (5, False), (1, True), (2, True), (5, True)]
)
def test_never_later_never_through_a_closed_pixel_and_the_waits_kept(kind, seed, smooth):
    # Fields independent in every pixel (a leg meets every pixel's weather where a long engine
    # step reads only its two ends: few shortcuts pay), or varying smoothly (fewer vertices).
    case = CASES[kind](seed, smooth=True, shape=(12, 15), closed=0.1) if smooth else CASES[kind](seed)
    raw = case.route
    s = raw.smoothed()
    arrive, leave = cases.schedule(raw)
    got_arrive, got_leave = cases.schedule(s)
    k = _kept(raw, s)
    # Never later: at every vertex kept, so at the end.
    assert s.cost <= raw.cost and np.all(got_arrive <= arrive[k])
    assert s.stats.voyage.hours == s.cost == got_arrive[-1] and s.stats.smoothing.cost_before == raw.cost
    assert len(s.pixels) < len(raw.pixels) if smooth else len(s.pixels) <= len(raw.pixels)
    assert s.method.endswith("+smoothed")
    # Every wait of the route is a vertex of the new one, left when the route left it.
    waited = np.flatnonzero(raw.stats.voyage.wait_h > 1e-9)
    assert set(waited) <= set(k)
    for i in waited:
        assert got_leave[list(k).index(i)] == pytest.approx(leave[i], abs=1e-9)
    # Every leg sailed again densely: at the reference's time, through no closed pixel.
    legs, half = case.legs, (raw.neighbourhood - 1) // 2
    for j in range(len(k) - 1):
        p, q = s.vertices[j], s.vertices[j + 1]
        assert legs.arrive(p, q, got_leave[j]) == pytest.approx(got_arrive[j + 1], rel=1e-12)
        if np.abs(q - p).max() <= half:  # an engine step (checked in test_timed_legs)
            continue
        want, _ = case.sail(p, q, got_leave[j], n=8000)
        assert math.isfinite(want) and got_arrive[j + 1] == pytest.approx(want, rel=5e-4)


def test_a_wait_for_the_ice_to_open_is_kept_by_hand():
    # Planar 10 km pixels, 5 x 12: a band of closed ice over columns 5-6 on the first chart, all
    # open water (12 kn) from the second at 5 h. The ship waits at the band's edge (column 4)
    # until 5 h; smoothed: a straight leg there, the wait, a straight leg on to the end.
    stage = np.full((3, 5, 12), 55)
    stage[0, :, 5:7] = 93
    ds = planar_season(stage, hours=[0.0, 5.0, 48.0])
    raw = route_season(ds, (0, 0), (4, 11), speed=cases.TABLE, concentration_limit=False, smooth=False)
    s = route_season(ds, (0, 0), (4, 11), speed=cases.TABLE, concentration_limit=False)
    kmh = 1.0 / float(np.float32(1.0 / (12.0 * KM_PER_NM)))
    ((at, _, since, hours),) = raw.stats.voyage.waits
    ((at_s, _, since_s, hours_s),) = s.stats.voyage.waits
    assert at[1] == 4 and at_s == at and len(s.pixels) == 3  # start, the wait, the end
    first = math.hypot(at[0] * 10.0, 40.0) / kmh
    rest = math.hypot((4 - at[0]) * 10.0, 70.0) / kmh
    assert s.cost == pytest.approx(5.0 + rest, rel=1e-12) and s.cost <= raw.cost
    assert hours_s == pytest.approx(5.0 - first, rel=1e-9) and since_s <= since
    assert (
        s.stats.smoothing.waits_added == 0 and s.stats.voyage.charts_used == raw.stats.voyage.charts_used[:2]
    )


def test_a_zone_closed_until_ten_hours_is_waited_for_and_never_entered_while_closed():
    # 21 x 31 pixels of 0.1 deg from (60, 0), calm: a wall at 1.5 E closed for the first 10 h.
    fc = forecast(frames=9, ce=0.0, cn=0.0)
    wall = pytest.importorskip("shapely.geometry").box(1.45, 59.0, 1.55, 63.0)
    zone = Zone(wall, active=(0.0, 10.0))
    a, b = (61.0, 0.2), (61.0, 2.8)
    raw = route_time(fc, a, b, vessel=CALM, neighbourhood=3, zones=[zone], smooth=False)
    s = raw.smoothed()
    assert s.cost <= raw.cost and len(s.pixels) == 3
    ((at, (lat, lon), _, _),) = s.stats.voyage.waits
    assert at[1] == 14 and s.stats.voyage.wait_h[0] == 0.0 < s.stats.voyage.wait_h[1]
    # 10 h, then the great circle from the wait to the end at 12 kn.
    assert s.cost == pytest.approx(10.0 + _core.haversine_km(lat, lon, *b) / KM_PER_NM / 12.0, rel=1e-12)
    # Sampled every half pixel, the legs meet the wall's pixels only after it opened.
    closed = rasterise_zone(zone, raw.chart)
    elapsed = np.concatenate([[0.0], np.cumsum(s.costs())])
    for j in range(len(s.pixels) - 1):
        on_wall = closed[tuple(s.sample_pixels(j, j + 1).T)].any()
        assert not on_wall or elapsed[j] + s.stats.voyage.wait_h[j] >= 10.0


def test_via_points_are_kept():
    rng = np.random.default_rng(2)
    fc = forecast(frames=4, ce=rng.uniform(-0.5, 0.5, (4, 21, 31)), cn=rng.uniform(-0.5, 0.5, (4, 21, 31)))
    via = (61.5, 1.0)
    r = route_time(fc, (60.2, 0.2), (61.8, 2.8), vessel=CALM, via=[via], neighbourhood=5)
    raw = route_time(fc, (60.2, 0.2), (61.8, 2.8), vessel=CALM, via=[via], neighbourhood=5, smooth=False)
    assert [15, 10] in r.pixels.tolist() and r.cost <= raw.cost and len(r.pixels) < len(raw.pixels)


def test_the_least_danger_route_is_left_as_found_and_says_why():
    wind = np.zeros((21, 31))
    wind[:, 15] = 20.0  # a storm wall: no route avoids the danger zones
    fc = forecast(wind=wind, ce=0.0, cn=0.0)
    ship = Vessel(speed_kn=12.0, speed_loss="none", danger_wind_ms=11.0)
    r = route_time(fc, (61.0, 0.2), (61.0, 2.8), vessel=ship, neighbourhood=3)
    assert r.stats.through_danger and r.stats.smoothing is None and "smoothed" not in r.method
    assert any(n.startswith("not smoothed: the least-danger route (Sotnikova 2009)") for n in r.notes)
    with pytest.raises(ValueError, match="least-danger route"):
        r.smoothed()


def test_the_kara_sea_voyage_of_the_issue_has_fewer_legs_and_is_no_later(tmp_path, capsys):
    from seaway.vessel import load
    from seaway.weather import kara_autumn, route_ice_weather

    ice, gale = kara_autumn()
    ship = load("pc6-general-cargo")
    a, b = (70.5, 58.0), (73.5, 80.0)
    options = dict(ice_class=ship.ice_class, vessel=ship.vessel, departure="2026-10-01T06:00")
    raw = route_ice_weather(ice, gale, a, b, smooth=False, **options)
    s = raw.smoothed()
    assert len(raw.legs()) == 6 and len(s.legs()) == 4  # Andreeva 2021's speeds
    assert raw.cost == pytest.approx(37.332, abs=1e-3) and s.cost == pytest.approx(37.226, abs=1e-3)
    assert s.stats.voyage.charts_used == raw.stats.voyage.charts_used
    # The command line (POLARIS's speed limits for a Polar Class): says it smoothed, and how.
    ice.to_netcdf(tmp_path / "ice.nc")
    gale.to_netcdf(tmp_path / "gale.nc")
    argv = [str(tmp_path / "ice.nc"), "--forecast", str(tmp_path / "gale.nc"), "--from=70.5,58"]
    argv += ["--to=73.5,80", "--depart", "2026-10-01T06:00", "--vessel-file", "pc6-general-cargo"]
    assert main(["route", *argv]) == 0
    out, err = capsys.readouterr()
    assert (
        "smoothed on the clock" in err and "not smoothed" not in err and "; 2 legs, 1 course changes" in out
    )
    assert main(["route", *argv, "--no-smooth", "-q"]) == 0
    assert "; 5 legs, 4 course changes" in capsys.readouterr().out


def test_a_season_opened_from_a_file_is_smoothed_unless_asked_not_to(tmp_path, capsys):
    import seaway
    from support.seasons import retreating_edge

    path = tmp_path / "week.nc"
    retreating_edge(days=4).to_netcdf(path)
    season = seaway.open_season(str(path))
    a, b = (71.0, 70.0), (76.0, 74.0)
    s, raw = season.route(a, b), season.route(a, b, smooth=False)
    assert s.method == raw.method + "+smoothed" and s.cost <= raw.cost and len(s.pixels) < len(raw.pixels)
    argv = ["season", str(path), "--from=71,70", "--to=76,74"]
    assert main(argv) == 0
    out, err = capsys.readouterr()
    assert "smoothed through the charts" in err and f"{s.cost:.2f} h" in out
    assert main([*argv, "--no-smooth", "-q"]) == 0
    assert f"{raw.cost:.2f} h" in capsys.readouterr().out


def test_a_leg_across_the_antimeridian_is_the_rolled_seasons_leg():
    # A 360-degree chart of open water (5 deg of longitude, 0.5 deg of latitude): from 152.5 E to
    # 152.5 W across the seam the smoothed route is one leg, as in the season rolled half a turn.
    stage = np.full((2, 8, 72), 55)
    lat, lon = 80.5 - 0.5 * np.arange(8), np.arange(-177.5, 180.0, 5.0)
    ds = planar_season(stage, hours=[0.0, 48.0]).rename(y="lat", x="lon").assign_coords(lat=lat, lon=lon)
    rolled = ds.copy(data={k: np.roll(v.values, 36, axis=-1) for k, v in ds.data_vars.items()})
    got = []
    for season, c0, c1 in ((ds, 66, 5), (rolled, 30, 41)):
        raw = route_season(
            season,
            (lat[7], lon[c0]),
            (lat[1], lon[c1]),
            speed=cases.TABLE,
            concentration_limit=False,
            smooth=False,
        )
        got.append((raw, raw.smoothed()))
    (raw, s), (raw_rolled, s_rolled) = got
    assert s.pixels.tolist() == [[7, 66], [1, 5]] and s_rolled.pixels.tolist() == [[7, 30], [1, 41]]
    assert s.cost == pytest.approx(s_rolled.cost, rel=1e-12) and s.cost < raw.cost
    kmh = 1.0 / float(np.float32(1.0 / (12.0 * KM_PER_NM)))
    assert s.cost == pytest.approx(s.length / kmh, rel=1e-9) and s.length < raw.length < 1300
