"""Ice and weather in one voyage (seaway.models.IceWeatherTime, route_ice_weather): the ice
chart's speed changed by the forecast, exact against a brute force over all paths, by hand on
one kind of ice, the class's limits, and on the real ROMS ice and currents."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway.base.units import KM_PER_NM, KNOTS_PER_MS
from seaway.ice.seasongrid import SeasonGrid
from seaway.icenav.season import route_season
from seaway.models import IceWeatherTime
from seaway.weather import ForecastGrid, Vessel, route_ice_weather
from support.forecasts import forecast
from support.reference import haversine
from support.reference_weather import Weather, ice_weather_best_arrival
from support.seasons import DAY0, retreating_edge

ROMS = "ocean_model/metno_ROMS_Arctic20_1to5Feb_2016.nc"
SHIP = Vessel(speed_kn=12.0, displacement_t=15000.0)


def _forecast_on(ds, frames=1, hours=6, **fields):
    """A CF forecast on the grid of the season `ds` from its first chart (support.forecasts)."""
    return forecast(
        lat=ds["lat"].values,
        lon=ds["lon"].values,
        start=ds["time"].values[0],
        frames=frames,
        hours=hours,
        **fields,
    )


def test_calm_weather_gives_the_ice_season_route_exactly():
    ds = retreating_edge()
    a, b = (71.0, 70.0), (76.0, 74.0)
    ice = route_season(ds, a, b, ice_class="Arc7", v0_kn=12.0)
    calm = _forecast_on(ds, frames=4, hours=24, ce=0.0, cn=0.0)
    both = route_ice_weather(ds, calm, a, b, ice_class="Arc7", vessel=SHIP)
    assert both.cost == pytest.approx(ice.cost, rel=1e-12)
    assert both.pixels.tolist() == ice.pixels.tolist()
    v = both.stats.voyage
    assert v.departure == DAY0 and v.ice_class == "Arc7" and v.charts_used == ice.stats.voyage.charts_used
    assert "2026-07-01T00:00 to 2026-07-04T00:00, every 24 h" in v.forecast
    # The voyage outlasts the forecast's last frame: persistence, said.
    assert any("after the forecast's last time" in s for s in both.assumptions) == (
        v.arrival > calm.time.values[-1]
    )


def test_current_along_a_meridian_adds_to_the_speed_in_ice_by_hand():
    # One kind of ice everywhere: 5/10 of 0.7 m, so an Arc7 (h_pass 1.4 m) makes
    # V = (1 - 0.7 / 1.4) x 12 = 6 kn (Andreeva 2021); a 1 m/s northward current adds 1.944 kn on
    # a route due north.
    lat, lon = np.arange(72.0, 74.01, 0.1), np.arange(60.0, 61.01, 0.1)
    shape = (1, lat.size, lon.size)
    ds = xr.Dataset(
        {
            "CT": (("time", "lat", "lon"), np.full(shape, 5.0)),
            "thickness": (("time", "lat", "lon"), np.full(shape, 0.7)),
        },
        coords={"time": [DAY0], "lat": lat, "lon": lon},
    )
    a, b = (72.0, 60.5), (74.0, 60.5)
    north = route_ice_weather(
        ds, _forecast_on(ds, ce=0.0, cn=1.0), a, b, ice_class="Arc7", vessel=SHIP, neighbourhood=3
    )
    south = route_ice_weather(
        ds, _forecast_on(ds, ce=0.0, cn=1.0), b, a, ice_class="Arc7", vessel=SHIP, neighbourhood=3
    )
    nm = float(haversine(72.0, 60.5, 74.0, 60.5)) / KM_PER_NM
    v_ice = 1.0 / (float(np.float32(1.0 / (6.0 * KM_PER_NM))) * KM_PER_NM)  # hours per km in float32
    assert v_ice == pytest.approx(6.0, rel=1e-7)
    assert north.cost == pytest.approx(nm / (v_ice + KNOTS_PER_MS), rel=1e-12)
    assert south.cost == pytest.approx(nm / (v_ice - KNOTS_PER_MS), rel=1e-12)
    assert np.all(north.pixels[:, 1] == 5)  # due north along the meridian
    # One chart, valid for a day by default: a longer voyage assumes it holds, and says so.
    assert south.cost > 24 and any("the last chart was assumed to hold" in s for s in south.assumptions)
    assert not any("the last chart" in s for s in north.assumptions)


def test_the_class_limits_still_close_the_ice_a_following_current_crosses():
    # A band of 8/10 thin first-year ice (SA 87, 0.3-0.7 m: 0.7 m by default) across the way:
    # Arc7 (h_pass 1.4 m, up to 8/10) crosses it at 6 kn; Arc4 (0.8 m, up to 6/10) may not
    # enter it, however strong the current that would carry it through; it passes west of the
    # band's end.
    lat, lon = np.arange(72.0, 74.01, 0.1), np.arange(60.0, 64.01, 0.1)
    shape = (1, lat.size, lon.size)
    ct, sa = np.zeros(shape), np.full(shape, np.nan)
    band = (lat[:, None] > 72.85) & (lat[:, None] < 73.15) & (lon[None, :] > 60.45)
    ct[0][band], sa[0][band] = 8.0, 87.0
    ds = xr.Dataset(
        {"CT": (("time", "lat", "lon"), ct), "SA": (("time", "lat", "lon"), sa)},
        coords={"time": [DAY0], "lat": lat, "lon": lon},
    )
    fc = _forecast_on(ds, ce=0.0, cn=1.5)
    a, b = (72.0, 63.5), (74.0, 63.5)
    arc7 = route_ice_weather(ds, fc, a, b, ice_class="Arc7", vessel=SHIP)
    arc4 = route_ice_weather(ds, fc, a, b, ice_class="Arc4", vessel=SHIP)
    # Along every leg (smoothed: straight legs through the charts), sampled every half pixel.
    crossed = band[tuple(arc7.sample_pixels().T)]
    assert crossed.any() and not band[tuple(arc4.sample_pixels().T)].any()
    assert arc4.pixels[:, 1].min() <= 4 and arc4.cost > arc7.cost  # round the band's west end
    across = np.broadcast_to((lat[:, None] > 72.85) & (lat[:, None] < 73.15), band.shape)
    narrow = ds.assign(
        CT=(ds.CT.dims, np.where(across, 8.0, ct)), SA=(ds.SA.dims, np.where(across, 87.0, sa))
    )
    with pytest.raises(seaway.NoRouteError, match="class Arc4"):
        route_ice_weather(narrow, fc, a, b, ice_class="Arc4", vessel=SHIP)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_ice_and_weather_equal_the_brute_force_over_all_paths(seed):
    rng = np.random.default_rng(seed)
    rows, cols, charts, frames = 3, 4, 3, 5
    lat, lon = 70.0 + 0.5 * np.arange(rows), 30.0 + 0.5 * np.arange(cols)
    # Three daily ice charts: thickness 0-0.8 m (an Arc7 makes 5.1-12 kn), some pixels over the
    # class's 8/10 (closed) in some charts; the ship may wait for a later chart.
    ct = rng.choice([0.0, 3.0, 6.0, 9.0], size=(charts, rows, cols), p=[0.3, 0.3, 0.25, 0.15])
    ct[:, 0, 0] = ct[:, -1, -1] = 3.0
    ice = xr.Dataset(
        {
            "CT": (("time", "lat", "lon"), ct),
            "thickness": (("time", "lat", "lon"), rng.uniform(0.0, 0.8, (charts, rows, cols))),
        },
        coords={"time": DAY0 + np.arange(charts) * np.timedelta64(12, "h"), "lat": lat, "lon": lon},
    )
    # Mild currents and waves changing every 6 h (FIFO), and a storm above 20 m/s fixed in time.
    wind = np.where(rng.random((rows, cols)) < 0.15, 24.0, 8.0)
    wind[0, 0] = wind[-1, -1] = 8.0
    fields = dict(
        ce=rng.uniform(-0.8, 0.8, (frames, rows, cols)),
        cn=rng.uniform(-0.8, 0.8, (frames, rows, cols)),
        hs=rng.uniform(0.0, 1.5, (frames, rows, cols)),
        wdir=rng.uniform(0, 360, (frames, rows, cols)),
        wind=np.broadcast_to(wind, (frames, rows, cols)),
    )
    fc = _forecast_on(ice, frames=frames, hours=6, **fields)
    ship = Vessel(speed_kn=12.0, displacement_t=15000.0, max_wind_ms=20.0)
    grid = SeasonGrid(ice)
    model = IceWeatherTime(grid, ForecastGrid(fc), "Arc7", ship)
    weather = Weather({k: fc[k].values for k in fields}, lat, lon, max_wind_ms=20.0)
    best = ice_weather_best_arrival(
        model.hours_per_km, list(model.valid_from_h), weather, (0, 0), (rows - 1, cols - 1), k=3
    )
    chart = seaway.prepare(grid, neighbourhood=3)
    for method in ("dijkstra", "astar"):
        try:
            got = chart.route((lat[0], lon[0]), (lat[-1], lon[-1]), model=model, method=method).cost
        except seaway.NoRouteError:
            got = np.inf
        assert got == pytest.approx(best, rel=1e-9), method
    assert np.isfinite(best)


@pytest.mark.needs_data(ROMS)
def test_real_roms_ice_and_currents_in_one_voyage(shared_data):
    """MET Norway's ROMS Arctic-20km, 1-5 Feb 2016: its own sea ice (aice, hice) as a season of
    daily charts and its barotropic currents (ubar, vbar) as the forecast, both moved from the
    polar stereographic grid onto lat/lon; an Arc7 from the ice-free Barents Sea into the ice
    north-east of Svalbard."""
    pytest.importorskip("pyproj")
    from seaway.weather import read_forecast, to_latlon

    ds = read_forecast(shared_data / ROMS)[["aice", "hice", "ubar", "vbar", "mask", "polar_stereographic"]]
    lat, lon = np.arange(72.0, 80.01, 0.1), np.arange(20.0, 50.01, 0.25)
    on = to_latlon(ds, lat, lon)
    land = (on["mask"] < 0.5) | on["aice"].isel(time=0).isnull()
    season = on[["aice", "hice"]].assign(land=land)
    currents = on[["ubar", "vbar"]]
    a, b = (73.0, 30.0), (79.6, 38.0)
    ship = Vessel(speed_kn=12.0, displacement_t=15000.0)
    both = route_ice_weather(season, currents, a, b, ice_class="Arc7", vessel=ship)
    ice = route_season(season, a, b, ice_class="Arc7", v0_kn=12.0)
    m = IceWeatherTime(SeasonGrid(season), ForecastGrid(currents), "Arc7", ship)
    assert m.departure == np.datetime64("2016-02-01T12:00")
    # The barotropic currents (a few cm/s) change a two-day passage by minutes, not hours.
    assert abs(both.cost - ice.cost) < 0.01 * ice.cost and both.cost != pytest.approx(ice.cost, rel=1e-6)
    # The ice near the end eases on a later daily chart: the ship waits for it.
    assert both.stats.voyage.hours_waiting > 1.0 and both.stats.voyage.waits[0].since > m.departure
    # Never in ice the class may not enter in the chart valid when the ship is there.
    t = np.concatenate([[0.0], np.cumsum(both.costs())])
    k = np.searchsorted(m.valid_from_h, t, side="right") - 1
    assert all(np.isfinite(m.hours_per_km[kk][tuple(p)]) for kk, p in zip(k, both.pixels))
    hice = on["hice"].values
    assert np.nanmax([hice[kk][tuple(p)] for kk, p in zip(k, both.pixels)]) > 0.3  # it meets ice
    with pytest.raises(ValueError, match=r"end .* is in ice class Arc4 may not enter"):
        route_ice_weather(season, currents, a, b, ice_class="Arc4", vessel=ship)


@pytest.mark.slow
def test_the_readme_kara_sea_autumn_example():
    from pathlib import Path

    from seaway.vessel import load
    from seaway.weather import kara_autumn

    ice, gale = kara_autumn()
    ship = load("pc6-general-cargo")
    a, b = (70.5, 58.0), (73.5, 80.0)
    r = route_ice_weather(
        ice, gale, a, b, ice_class=ship.ice_class, vessel=ship.vessel, departure="2026-10-01T06:00"
    )
    alone = route_season(ice, a, b, ice_class="PC6", v0_kn=ship.vessel.speed_kn, departure="2026-10-01T06:00")
    # Eastbound the westerly sea follows the ship (Khokhlov's small gain) and the coastal current
    # carries it: quicker than through the ice alone; westbound, into the sea, slower.
    assert r.cost < alone.cost
    back = route_ice_weather(
        ice, gale, b, a, ice_class=ship.ice_class, vessel=ship.vessel, departure="2026-10-01T06:00"
    )
    back_alone = route_season(
        ice, b, a, ice_class="PC6", v0_kn=ship.vessel.speed_kn, departure="2026-10-01T06:00"
    )
    assert back.cost > back_alone.cost
    readme = (Path(__file__).parents[2] / "README.md").read_text()
    eta = str(r.stats.voyage.arrival)[:16].replace("T", " ")
    assert f"# {r.cost:.1f} h, arrival {eta} UTC" in readme


def test_a_polar_class_takes_the_polaris_speed_limit_in_ice_by_hand():
    # 10/10 thick first-year ice (SA 93): a PC6's RIO is 10 x -1 = -10, elevated risk, so
    # POLARIS limits it to 3 kn (MSC.1/Circ.1519 Table 1.4); a 1 m/s current due north adds
    # 1.944 kn on a route due north. A Register Arc4 (h_pass 0.8 m) may not enter 2 m ice at all.
    lat, lon = np.arange(72.0, 73.01, 0.1), np.arange(60.0, 61.01, 0.1)
    shape = (1, lat.size, lon.size)
    ds = xr.Dataset(
        {
            "CT": (("time", "lat", "lon"), np.full(shape, 10.0)),
            "CA": (("time", "lat", "lon"), np.full(shape, 10.0)),  # POLARIS reads partials
            "SA": (("time", "lat", "lon"), np.full(shape, 93.0)),
        },
        coords={"time": [DAY0], "lat": lat, "lon": lon},
    )
    fc = _forecast_on(ds, ce=0.0, cn=1.0)
    a, b = (72.0, 60.5), (73.0, 60.5)
    pc6 = route_ice_weather(ds, fc, a, b, ice_class="PC6", vessel=SHIP, neighbourhood=3, speed="class")
    nm = float(haversine(72.0, 60.5, 73.0, 60.5)) / KM_PER_NM
    v_ice = 1.0 / (float(np.float32(1.0 / (3.0 * KM_PER_NM))) * KM_PER_NM)  # hours per km in float32
    assert pc6.cost == pytest.approx(nm / (v_ice + KNOTS_PER_MS), rel=1e-12)
    with pytest.raises(ValueError, match="class Arc4 may go nowhere in any chart of the season"):
        route_ice_weather(ds, fc, a, b, ice_class="Arc4", vessel=SHIP, neighbourhood=3, speed="class")
