"""The voyage in time on an ice chart (OpenChart.route): every leg timed by the ship's speed in
its ice (the ship's ice curve, else Andreeva 2021), ice the ship cannot cross on its own avoided
or escorted and marked, the quickest route beside the least-impact one, the schedule from a
departure in every output, the chart's age, and a leg's time, speed and ice read at the same
pixels. Analytic cases on a band of one ice type (its km by dense sampling, speeds by hand)."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway.cli import main
from seaway.errors import NoRouteError
from seaway.vessel import IceCurve, Vessel, load

KN = 1.852
A, B = (73.05, 61.05), (73.05, 78.95)


def band_chart(tmp_path, stage=93, ct=10.0, west=66.0, east=70.0, date="2026-02-01", name="band.nc"):
    """A NetCDF ice chart: open water at 70-76 N, 60-80 E with a band of one stage of development
    between `west` and `east` (CT tenths), dated `date`."""
    lat, lon = np.round(np.arange(70.05, 76, 0.1), 2), np.round(np.arange(60.05, 80, 0.1), 2)
    inside = (lon > west) & (lon < east)
    ctv = np.where(inside, ct, 0.0)[None, :].repeat(lat.size, 0)
    sa = np.where(inside, float(stage), np.nan)[None, :].repeat(lat.size, 0)
    dims = ("lat", "lon")
    ds = xr.Dataset(
        {"CT": (dims, ctv), "CA": (dims, ctv), "SA": (dims, sa), "land": (dims, np.zeros(ctv.shape, bool))},
        coords={"lat": lat, "lon": lon},
        attrs={"time_coverage_start": date},
    )
    path = tmp_path / name
    ds.to_netcdf(path)
    return str(path)


def km_between(route, west, east, n=4000):
    """km of `route` between two meridians, by dense sampling of its legs (great circles)."""
    from seaway._core import haversine_km
    from seaway.base import sphere

    total, c = 0.0, route.coords
    for a, b in zip(c[:-1], c[1:]):
        lat, lon = sphere.intermediate(a[0], a[1], b[0], b[1], (np.arange(n) + 0.5) / n)
        total += haversine_km(a[0], a[1], b[0], b[1]) * np.mean((lon > west) & (lon < east))
    return float(total)


def test_a_ship_with_no_speed_of_its_own_is_escorted_and_marked_or_refused(tmp_path):
    """Thick first-year ice (93) is 1.6 m at the middle of its WMO range: Arc7 (1.4 m, Andreeva
    2021) has no speed of its own there. Without escort no route crosses the band; with it the
    band is crossed at the escort's speed, its km marked on the legs."""
    chart = seaway.open_chart(band_chart(tmp_path), vessel="Arc7")
    with pytest.raises(NoRouteError) as info:
        chart.route(A, B)
    assert "the weakest class that gets through is Arc8" in str(info.value)  # 2.1 m: it passes 1.6 m
    assert "with an icebreaker's escort (escort=True, --escort) an Arc7 ship gets through" in str(info.value)
    r = chart.route(A, B, escort=True, escort_speed_kn=5.0)
    inside = km_between(r, 66, 70)
    s = r.summary()
    assert s["escorted_km"] == pytest.approx(inside, rel=0.02)
    assert s["time_h"] == pytest.approx((r.length - inside) / (12 * KN) + inside / (5 * KN), rel=0.01)
    legs = r.legs()
    assert sum(leg.escorted_km for leg in legs) == pytest.approx(s["escorted_km"], rel=1e-9)
    assert all(np.isfinite(leg.time_h) and leg.speed_kn > 0 for leg in legs)
    assert any("under icebreaker escort 5 kn (given)" in n for n in r.notes)
    assert "under icebreaker escort:" in str(r) and "escort km" in str(r)


def test_the_ice_curve_gives_the_speed_by_the_equivalent_thickness(tmp_path):
    """The Arc7 LNG carrier's curve: 19.5 kn at 0 m, 2 kn at 2.1 m, linear. In 6/10 of thick
    first-year ice (1.6 m) the equivalent thickness is 0.96 m: 19.5 - 17.5 x 0.96 / 2.1 kn."""
    ship = load("arc7-lng-carrier")
    chart = seaway.open_chart(band_chart(tmp_path, ct=6.0))
    r = chart.route(A, B, vessel=ship)
    inside = km_between(r, 66, 70)
    v = 19.5 - 17.5 * (0.6 * 1.6) / 2.1
    assert r.summary()["time_h"] == pytest.approx(
        (r.length - inside) / (19.5 * KN) + inside / (v * KN), rel=0.01
    )
    assert "the ship's ice curve (0 m 19.5 kn, 2.1 m 2 kn)" in r.ice_speed.model
    assert "h_eq = C/10 x h" in r.ice_speed.model and "thick first-year ice 1.60 m" in r.ice_speed.model
    # a curve that ends before the ice's equivalent thickness: no speed of its own there
    weak = Vessel(speed_kn=14.0, ice_class="Arc4", ice_curve=IceCurve((0.0, 0.8), (14.0, 2.0), "test"))
    with pytest.raises(NoRouteError):
        chart.route(A, B, vessel=weak)


def test_the_quickest_route_beside_the_least_impact_one(tmp_path):
    """Medium first-year ice (91, 0.95 m: Arc7 at 12 x (1 - 0.95/1.4) = 3.86 kn) from 64 to 76 E
    except a lead of open water at 73.5-74.5 N: the least-impact route and the quickest go
    through the lead, both times are the line integral of hours per km, and time <= impact's."""
    path = band_chart(tmp_path, stage=91, west=64.0, east=76.0)
    ds = xr.open_dataset(path).load()
    lead = (ds.lat > 73.5) & (ds.lat < 74.5)
    ds["CT"] = ds.CT.where(~lead, 0.0)
    ds["SA"] = ds.SA.where(~lead)
    ds.to_netcdf(tmp_path / "lead.nc")
    chart = seaway.open_chart(str(tmp_path / "lead.nc"), vessel="Arc7")
    impact = chart.route((72.05, 61.05), (72.05, 78.95))
    quick = chart.route((72.05, 61.05), (72.05, 78.95), objective="time")
    assert quick.unit == "h" and quick.cost == pytest.approx(quick.summary()["time_h"], rel=0.01)
    assert quick.cost <= impact.summary()["time_h"] + 1e-9
    # straight through the ice: 12 deg of longitude (about 390 km at 72 N) at 3.86 kn; the lead
    # is quicker
    slow = 12 * (1 - 0.95 / 1.4)
    assert quick.cost < 400 / (slow * KN)  # about 400 km of ice straight across


def test_depart_gives_every_waypoint_its_eta_in_every_output(tmp_path):
    path = band_chart(tmp_path, stage=87)  # thin first-year, 0.5 m: Arc7 at 12 x (1 - 0.5/1.4)
    outs = [tmp_path / f"r.{x}" for x in ("geojson", "rtz", "csv", "gpx")]
    code = main(
        [
            "route",
            path,
            "--from",
            "73.05,61.05",
            "--to",
            "73.05,78.95",
            "--vessel",
            "Arc7",
            "--depart",
            "2026-02-02T06:00",
            "-q",
        ]
        + [a for o in outs for a in ("--out", str(o))]
    )
    assert code == 0
    props = json.loads(outs[0].read_text())["properties"]
    hours = props["time_h"]
    arrival = np.datetime64("2026-02-02T06:00") + np.timedelta64(int(round(hours * 3600)), "s")
    assert props["departure"] == "2026-02-02T06:00:00Z" and props["arrival"] == f"{arrival}Z"
    ns = {"rtz": "http://www.cirm.org/RTZ/1/0"}
    sched = list(ET.parse(outs[1]).getroot().iter(f"{{{ns['rtz']}}}scheduleElement"))
    assert sched[0].get("etd") == "2026-02-02T06:00:00Z" and sched[-1].get("eta") == f"{arrival}Z"
    assert len(sched) == len(props["waypoint_schedule"]) >= 2
    assert "2026-02-02T06:00:00Z" in outs[3].read_text()  # GPX: the waypoints' times
    csv = [x for x in outs[2].read_text().splitlines() if not x.startswith("#")]
    assert "eta" in csv[0].lower()
    chart = seaway.open_chart(path, vessel="Arc7")
    r = chart.route(A, B, depart="2026-02-02T06:00")
    legs = r.legs()
    assert str(legs[-1].arrive) == str(arrival) and sum(leg.time_h for leg in legs) == pytest.approx(
        hours, rel=1e-9
    )
    # the chart (2026-02-01) is a day older than the departure, within the limit: dated, not warned
    assert any(n.startswith("ice chart of 2026-02-01: +1.2 days at departure") for n in r.notes)
    assert not any(n.startswith("warning") for n in r.notes)
    late = chart.route(A, B, depart="2026-02-20")
    assert any("is 20.2 days older than the voyage's last leg" in n for n in late.notes)


def test_the_stage_thickness_is_stated_and_editable(tmp_path):
    chart = seaway.open_chart(band_chart(tmp_path, stage=91), vessel="Arc7")
    mid = chart.route(A, B)
    upper = chart.route(A, B, stage_thickness="upper")
    given = chart.route(A, B, stage_thickness={91: 0.7})
    inside = km_between(mid, 66, 70)
    for r, h in ((mid, 0.95), (upper, 1.2), (given, 0.7)):
        v = 12 * (1 - h / 1.4)
        assert r.summary()["time_h"] == pytest.approx(
            (r.length - inside) / (12 * KN) + inside / (v * KN), rel=0.01
        )
    assert "the middle of its WMO range (WMO-No. 259): medium first-year ice 0.95 m" in mid.ice_speed.model
    assert "as given, the middle of the WMO range for the others" in given.ice_speed.model


def test_a_legs_time_speed_and_ice_come_from_the_same_pixels(tmp_path):
    """On a chart of several stages (thin, medium and thick first-year ice), a leg whose
    governing stage makes the ship alone slower than the escort (6 kn: medium first-year at 3.86
    kn, thick at none) is the leg that is escorted, and the other way round; leg hours add up to
    the voyage's and match the legs sampled densely."""
    lat, lon = np.round(np.arange(70.05, 76, 0.1), 2), np.round(np.arange(60.05, 80, 0.1), 2)
    rng = np.random.default_rng(3)
    blocks = rng.choice([55, 87, 91, 93], size=(6, 10), p=[0.3, 0.3, 0.25, 0.15])
    sa = np.kron(blocks, np.ones((10, 20)))[: lat.size, : lon.size].astype(float)
    ct = np.where(sa == 55, 0.0, 10.0)
    dims = ("lat", "lon")
    ds = xr.Dataset(
        {
            "CT": (dims, ct),
            "CA": (dims, ct),
            "SA": (dims, np.where(sa == 55, np.nan, sa)),
            "land": (dims, np.zeros(ct.shape, bool)),
        },
        coords={"lat": lat, "lon": lon},
    )
    ds.to_netcdf(tmp_path / "blocks.nc")
    chart = seaway.open_chart(str(tmp_path / "blocks.nc"), vessel="Arc7")
    r = chart.route((70.55, 60.55), (75.45, 79.45), escort=True)
    speed = {55: 12.0, 87: 12 * (1 - 0.5 / 1.4), 91: 12 * (1 - 0.95 / 1.4), 93: 0.0}
    legs = r.legs()
    for leg in legs:
        stage = leg.environment["stage_of_development"].code
        governed_slow = np.isfinite(stage) and speed[int(stage)] < 6.0
        assert governed_slow == (leg.escorted_km > 0), leg
    assert sum(leg.time_h for leg in legs) == pytest.approx(r.summary()["time_h"], rel=1e-12)
    from seaway._core import haversine_km
    from seaway.base import sphere

    per = np.vectorize(lambda s: max(speed[int(s)], 6.0))  # the escort where the ship alone is slower
    for leg in legs:  # densely, independently: 2000 points per leg, the speed at each one's pixel
        a, b = leg.start, leg.end
        la, lo = sphere.intermediate(a[0], a[1], b[0], b[1], (np.arange(2000) + 0.5) / 2000)
        i = np.abs(lat[:, None] - la).argmin(0)
        j = np.abs(lon[:, None] - lo).argmin(0)
        hours = haversine_km(*a, *b) / 2000 * np.sum(1 / (per(sa[i, j]) * KN))
        assert leg.time_h == pytest.approx(hours, rel=0.03)


def test_the_vessel_file_drives_a_chart_route_on_the_command_line(tmp_path, capsys):
    path = band_chart(tmp_path, stage=93)
    out = tmp_path / "r.geojson"
    code = main(
        [
            "route",
            path,
            "--from",
            "73.05,61.05",
            "--to",
            "73.05,78.95",
            "--vessel-file",
            "arc7-lng-carrier",
            "--out",
            str(out),
            "-q",
        ]
    )
    err = capsys.readouterr().err
    assert code == 0, err
    assert (
        "vessel: Arc7 LNG carrier, Arc7, 19.5 kn (vessel file arc7-lng-carrier (shipped with seaway))" in err
    )
    props = json.loads(out.read_text())["properties"]
    r = seaway.open_chart(path, vessel="Arc7").route(A, B, vessel=load("arc7-lng-carrier"))
    assert props["time_h"] == pytest.approx(r.summary()["time_h"], rel=1e-12)
    inside = km_between(r, 66, 70)
    v = 19.5 - 17.5 * 1.6 / 2.1
    assert props["time_h"] == pytest.approx((r.length - inside) / (19.5 * KN) + inside / (v * KN), rel=0.01)


def test_a_season_routes_the_vessel_files_ship_and_dates_its_charts(tmp_path):
    """Two identical weekly charts: the Arc7 LNG carrier through the season takes the static
    chart's time by its ice curve (the season's step times are integrals over float32 hours per
    km); a voyage five days after a weekly chart crosses a chart over three days old: said."""
    path = band_chart(tmp_path, stage=93)
    one = xr.open_dataset(path).load()
    week = xr.concat([one, one], dim="time").assign_coords(
        time=np.array(["2026-02-01", "2026-02-08"], dtype="datetime64[ns]")
    )
    ship = load("arc7-lng-carrier")
    season = seaway.open_season(_write(week, tmp_path / "week.nc"))
    r = season.route(A, B, vessel=ship, depart="2026-02-01", smooth=False)
    static = seaway.open_chart(path).route(A, B, vessel=ship, objective="time", smooth=False)
    assert r.cost == pytest.approx(static.summary()["time_h"], rel=1e-3)
    assert r.stats.voyage.hours_waiting == 0 and not any(n.startswith("warning") for n in r.notes)
    assert any(n.startswith("vessel: Arc7 LNG carrier") for n in r.notes)
    late = season.route(A, B, vessel=ship, depart="2026-02-06")
    assert any("warning: the ice chart of 2026-02-01" in n and "add newer charts" in n for n in late.notes)


def _write(ds, path):
    ds.to_netcdf(path)
    return str(path)
