"""Schedules in every output of a route on a clock: the leg table's one time (the real one) and
speed made good, RTZ's calculated schedule, the times in GeoJSON, GPX and CSV, the HTML map's
ETA; departure, arrival and forecast recorded in each."""

from __future__ import annotations

import csv
import io
import json
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from seaway import export
from seaway.weather import Vessel, route_time
from support.forecasts import forecast

SHIP = Vessel(speed_kn=12.0, speed_loss="none")
RTZ = "{http://www.cirm.org/RTZ/1/0}"
GPX = "{http://www.topografix.com/GPX/1/1}"


@pytest.fixture(scope="module")
def voyage():
    rng = np.random.default_rng(3)
    fc = forecast(frames=6, ce=rng.uniform(-1, 1, (6, 21, 31)), cn=rng.uniform(-1, 1, (6, 21, 31)))
    return route_time(fc, (60.2, 0.2), (61.8, 2.8), vessel=SHIP, departure="2026-01-01T03:00")


def _times(route):
    """Hours after departure at every vertex, from the engine's step costs."""
    return np.concatenate([[0.0], np.cumsum(route.costs())])


def _at(h):
    return np.datetime64("2026-01-01T03:00", "s") + np.timedelta64(int(round(h * 3600)), "s")


def test_the_leg_table_has_one_time_the_real_one_and_the_speed_made_good(voyage):
    legs, t, wi = voyage.legs(), _times(voyage), voyage.waypoint_index
    assert sum(leg.time_h for leg in legs) == pytest.approx(voyage.cost, rel=1e-12)
    for leg, i, j in zip(legs, wi[:-1], wi[1:]):
        assert leg.time_h == pytest.approx(t[j] - t[i], rel=1e-12)  # the engine's hours, not nm / 12
        assert leg.speed_kn == pytest.approx(leg.distance_nm / leg.time_h, rel=1e-12)
        assert leg.arrive == _at(t[j]) and leg.depart == _at(t[i])
    assert {round(leg.speed_kn, 3) for leg in legs} != {12.0}  # the currents change it
    text = str(voyage)
    header = [line for line in text.splitlines() if line.startswith("leg ")][0]
    assert header.split() == ["leg", "from", "to", "course", "nm", "km", "kn", "hours", "ETA", "(UTC)"]
    assert "departure 2026-01-01T03:00:00Z, arrival " + str(_at(voyage.cost)) + "Z" in text
    assert "forecast forecast in memory (2026-01-01T00:00 to 2026-01-02T06:00, every 6 h)" in text


def test_rtz_carries_the_calculated_schedule(voyage):
    root = ET.fromstring(export.rtz(voyage))
    info = root.find(f"{RTZ}routeInfo")
    assert info.get("validityPeriodStart") == "2026-01-01T03:00:00Z"
    assert info.get("validityPeriodStop") == str(_at(voyage.cost)) + "Z"
    assert "forecast in memory" in info.get("optimizationMethod")
    elems = root.findall(f"{RTZ}schedules/{RTZ}schedule/{RTZ}calculated/{RTZ}scheduleElement")
    wps = root.findall(f"{RTZ}waypoints/{RTZ}waypoint")
    assert [e.get("waypointId") for e in elems] == [w.get("id") for w in wps]
    t, legs = _times(voyage), voyage.legs()
    assert elems[0].get("etd") == "2026-01-01T03:00:00Z" and elems[0].get("eta") is None
    for e, i, leg in zip(elems[1:], voyage.waypoint_index[1:], legs):
        assert e.get("eta") == str(_at(t[i])) + "Z" and float(e.get("speed")) == pytest.approx(
            leg.speed_kn, abs=0.005
        )
    assert elems[-1].get("etd") is None


def test_geojson_gpx_and_csv_carry_the_times(voyage):
    props = export.geojson(voyage)["properties"]
    t = _times(voyage)
    assert props["departure"] == "2026-01-01T03:00:00Z" and props["arrival"] == str(_at(voyage.cost)) + "Z"
    # the times at the vertices of its line: the waypoints every export gives
    assert props["vertex_times"] == [str(_at(t[i])) + "Z" for i in voyage.waypoint_index]
    assert props["forecast"].startswith("forecast in memory") and props["time_h"] == voyage.cost
    assert json.loads(json.dumps(props))["waypoint_schedule"][-1]["eta"] == props["arrival"]
    pts = ET.fromstring(export.gpx(voyage)).findall(f"{GPX}rte/{GPX}rtept")
    assert [p.find(f"{GPX}time").text for p in pts] == [str(_at(t[i])) + "Z" for i in voyage.waypoint_index]
    text = export.csv_text(voyage)
    comments = [line for line in text.splitlines() if line.startswith("#")]
    assert f"# departure 2026-01-01T03:00:00Z, arrival {props['arrival']}" in comments
    assert any(c.startswith("# forecast forecast in memory (2026-01-01T00:00") for c in comments)
    rows = list(
        csv.DictReader(io.StringIO("\n".join(line for line in text.splitlines() if not line.startswith("#"))))
    )
    assert rows[0]["etd"] == "2026-01-01T03:00:00Z" and rows[-1]["eta"] == props["arrival"]
    assert float(rows[1]["time_h"]) == pytest.approx(voyage.legs()[0].time_h, abs=5e-4)


def test_the_html_popups_give_the_eta(voyage):
    pytest.importorskip("folium")
    from seaway.output.popup import waypoint_popup as _popup

    legs, wi, t = voyage.legs(), voyage.waypoint_index, _times(voyage)
    second = _popup(voyage, 2, voyage.coords[wi[1]], legs[1], None)
    assert f"ETA {str(_at(t[wi[1]]))[:16].replace('T', ' ')} UTC" in second
    assert f"{legs[1].speed_kn:.1f} kn made good" in second
    last = _popup(voyage, len(wi), voyage.coords[-1], None, None)
    assert "forecast forecast in memory" in last and "ETD" not in last


def test_a_static_route_keeps_its_nominal_times():
    import seaway

    r = seaway.route(np.ones((10, 10)), (0, 0), (0, 9), neighbourhood=3)
    assert r.stats.voyage is None and "vertex_times" not in export.geojson(r)["properties"]
    assert "departure" not in export.csv_text(r) and "eta" not in export.csv_text(r).splitlines()[-3]


def test_a_fuel_route_has_its_schedule_from_its_hours_not_its_tonnes():
    from seaway.weather import FuelCurve, route_fuel

    fc = forecast(frames=6, ce=0.5, cn=0.0)
    fuel = FuelCurve.cubic(12.0, 1.0, 8.0, 14.0)
    r = route_fuel(
        fc,
        (60.2, 0.2),
        (61.8, 2.8),
        vessel=Vessel(speed_kn=12.0, speed_loss="none"),
        fuel=fuel,
        time_value_t_per_h=0.5,
        at_hours=6.0,
    )
    v = r.stats.voyage
    assert v.hours == pytest.approx(r.stats.fuel.hours, rel=1e-12) and r.unit.startswith("t")
    assert v.departure == np.datetime64("2026-01-01T06:00") and "one forecast frame" in v.assumptions[0]
    assert sum(leg.time_h for leg in r.legs()) == pytest.approx(r.stats.fuel.hours, rel=1e-12)
    assert export.geojson(r)["properties"]["arrival"] == str(v.arrival)[:19] + "Z"
