"""Time in ice (seaway.ice.speed, Route.with_ice_speed, `seaway route --speed`): Andreeva 2021's
V = F x V0 for Register classes, the POLARIS speed limits for Polar Classes, the model named in
every output, never the open-water time through ice. Analytic cases on a band of one ice type
(the band's km from its edges by Geod; the speed from the paper's formula by hand), and the real
CIS chart against dense sampling of the route's legs."""

import json
import xml.etree.ElementTree as ET

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway import export
from seaway._core import haversine_km
from seaway.base import sphere
from seaway.cli import main
from seaway.ice import chart_impact
from seaway.ice.speed import ice_speed

KN = 1.852  # km per nautical mile
CIS = ("ice_charts_sigrid3", "cis_eastern_arctic", "cis_SGRDREA_20201102T.gpkg")


def band(stage, ct=10.0):
    """Open water at 70-76 N, 60-80 E with a band of one stage at 66-70 E (CT 10/10)."""
    lat, lon = np.round(np.arange(70.05, 76, 0.1), 2), np.round(np.arange(60.05, 80, 0.1), 2)
    inside = (lon > 66) & (lon < 70)
    ctv = np.where(inside, ct, 0.0)[None, :].repeat(lat.size, 0)
    sa = np.where(inside, float(stage), np.nan)[None, :].repeat(lat.size, 0)
    dims = ("lat", "lon")
    return xr.Dataset(
        {"CT": (dims, ctv), "CA": (dims, ctv), "SA": (dims, sa), "land": (dims, np.zeros(ctv.shape, bool))},
        coords={"lat": lat, "lon": lon},
    )


def straight(ds, cls):
    """The route along 73.05 N from 61.05 E to 78.95 E: (route, km in the band, km outside)."""
    r = seaway.route(chart_impact(ds, cls), (73.05, 61.05), (73.05, 78.95), land=ds.land)
    r = r.smoothed()
    total = r.length
    inside = dense_km(r, lambda lat, lon: (lon > 66) & (lon < 70))
    return r, inside, total - inside


def dense_km(route, inside, n=4000):
    total, c = 0.0, route.coords
    for a, b in zip(c[:-1], c[1:]):
        lat, lon = sphere.intermediate(a[0], a[1], b[0], b[1], (np.arange(n) + 0.5) / n)
        total += haversine_km(a[0], a[1], b[0], b[1]) * np.mean(inside(lat, lon))
    return float(total)


@pytest.mark.parametrize(
    "stage, cls, knots",
    [
        (87, "Arc7", 12 * (1 - 0.5 / 1.4)),  # thin first-year, the middle of 0.3-0.7 m: 0.5 m
        (87, "Arc5", 12 * (1 - 0.5 / 1.0)),  # Arc5's h_pass 1.0 m: F = 0.5
        (91, "Arc7", 12 * (1 - 0.95 / 1.4)),  # medium first-year, the middle of 0.7-1.2 m
    ],
)
def test_andreeva_speed_across_a_band(stage, cls, knots):
    r, km_in, km_out = straight(band(stage), cls)
    timed = r.with_ice_speed(ice_speed(band(stage), cls, 12))
    expected = km_out / (12 * KN) + km_in / (knots * KN)
    s = timed.summary()
    assert s["time_h"] == pytest.approx(expected, rel=0.01)
    assert s["time_h"] > r.length / (12 * KN) + 1  # never the open-water time
    assert (
        s["speed_model"].startswith("Andreeva 2021: V = F x V0, V0 12 kn") and f"({cls}," in s["speed_model"]
    )
    name = {87: "thin first-year ice 0.50 m", 91: "medium first-year ice 0.95 m"}[stage]
    assert f"the middle of its WMO range (WMO-No. 259): {name}" in s["speed_model"]
    assert sum(leg.time_h for leg in timed.legs()) == pytest.approx(s["time_h"], rel=1e-12)
    # the upper end, asked for: thin first-year 0.7 m, medium 1.2 m
    upper = r.with_ice_speed(ice_speed(band(stage), cls, 12, stage_thickness="upper")).summary()
    h_pass = {"Arc7": 1.4, "Arc5": 1.0}[cls]
    slow = 12 * (1 - {87: 0.7, 91: 1.2}[stage] / h_pass)
    assert upper["time_h"] == pytest.approx(km_out / (12 * KN) + km_in / (slow * KN), rel=0.01)
    assert "the upper end of its WMO range" in upper["speed_model"]


def test_polaris_limits_a_polar_class_under_elevated_risk():
    """PC7 in 10/10 medium first-year ice: RIO = 10 x (-1) = -10, elevated risk (MSC.1/Circ.1519
    Table 1.3), so the circular's 3 kn; PC5 there: RIO 10 x 1 = 10, normal operation, 12 kn."""
    ds = band(91)
    r, km_in, km_out = straight(ds, "Arc7")
    pc7 = r.with_ice_speed(ice_speed(ds, "PC7", 12)).summary()
    assert pc7["time_h"] == pytest.approx(km_out / (12 * KN) + km_in / (3 * KN), rel=0.01)
    assert pc7["speed_model"] == (
        "IMO POLARIS (MSC.1/Circ.1519), PC7 row: 12 kn in normal operation, "
        "3 kn under elevated risk, none under special consideration"
    )
    pc5 = r.with_ice_speed(ice_speed(ds, "PC5", 12)).summary()
    assert pc5["time_h"] == pytest.approx(r.length / (12 * KN), rel=1e-9)


def test_ice_thicker_than_the_class_passes_gives_no_time_not_open_water_time(tmp_path):
    ds = band(93)  # thick first-year, the middle of 1.2-2.0 m, 1.6 m: Arc7 (1.4 m) gets F = 0
    r, km_in, _ = straight(ds, "Arc7")
    timed = r.with_ice_speed(ice_speed(ds, "Arc7", 12))
    s = timed.summary()
    assert s["time_h"] == np.inf and s["stopped_km"] == pytest.approx(km_in, rel=0.01)
    assert "time: none (12 kn in open water; in ice Andreeva 2021" in str(timed)
    assert f"no speed on {s['stopped_km']:.1f} km" in export.gpx(timed)
    props = export.geojson(timed)["properties"]
    assert "time_h" not in props and props["stopped_km"] == pytest.approx(km_in, rel=0.01)
    assert props["speed_model"] == s["speed_model"]
    with pytest.raises(ValueError, match="speeds in ice are for 12 kn in open water, not 10 kn"):
        timed.legs(10)


@pytest.mark.cli
def test_cli_speed_on_an_ice_chart_uses_the_ice_model(tmp_path, capsys):
    ds = band(87)
    path = tmp_path / "band.nc"
    ds.to_netcdf(path)
    r, km_in, km_out = straight(ds, "Arc7")
    outs = [tmp_path / "r.geojson", tmp_path / "r.rtz", tmp_path / "r.csv"]
    code = main(
        ["route", str(path), "--from", "73.05,61.05", "--to", "73.05,78.95", "--speed", "12", "-q"]
        + [a for o in outs for a in ("--out", str(o))]
    )
    out, err = capsys.readouterr()
    assert code == 0, err
    assert "timed by the ship's speed in the ice: Andreeva 2021: V = F x V0, V0 12 kn" in err
    props = json.loads(outs[0].read_text())["properties"]
    slow = 12 * (1 - 0.5 / 1.4)  # thin first-year ice, 0.5 m by default
    assert props["time_h"] == pytest.approx(km_out / (12 * KN) + km_in / (slow * KN), rel=0.01)
    assert props["speed_model"].startswith("Andreeva 2021")
    speeds = [
        float(leg.get("speedMax"))
        for leg in ET.parse(outs[1]).getroot().iter("{http://www.cirm.org/RTZ/1/0}leg")
        if leg.get("speedMax")
    ]
    assert min(speeds) < 12  # the legs through the band carry their mean speed
    assert outs[2].read_text().splitlines()[1].startswith("# speed in ice: Andreeva 2021")
    assert "time: " in out and "in ice Andreeva 2021" in out


@pytest.mark.needs_data(*CIS)
def test_real_cis_chart_times_agree_with_dense_sampling(shared_data):
    """CIS, 2 November 2020, Davis Strait -> the grey ice of northwestern Baffin Bay through
    bergy water, new and grey ice: Arc7 by Andreeva 2021 and PC6 by POLARIS, each against the legs sampled densely
    (4000 points per leg, the speed at each point's pixel)."""
    pytest.importorskip("pyogrio")
    from seaway.ice.grids import latlon_grid
    from seaway.ice.impact import governing_stage
    from seaway.ice.polaris import polaris_chart
    from seaway.ice.sigrid import read_sigrid3

    ds = read_sigrid3(str(shared_data.joinpath(*CIS)), latlon_grid(62, 84, -113, -22, (0.1, 0.25)))
    r = seaway.route(chart_impact(ds, "Arc7"), (64, -57), (74, -75), land=ds.land).smoothed()
    stage = governing_stage(ds).values
    upper = {55: 0.0, 81: 0.1, 82: 0.1, 83: 0.3, 84: 0.15, 85: 0.3, 87: 0.7, 86: 2.0, 91: 1.2, 93: 2.0}
    h = np.vectorize(lambda c: upper.get(c, np.nan))(np.nan_to_num(stage, nan=-1))
    h = np.where(ds.CT.values == 0, 0.0, h)
    arc7 = np.clip(1 - h / 1.4, 0, 1) * 12
    pc6 = polaris_chart(ds, "PC6", v0_kn=12).speed_kn.values
    for cls, knots in (("Arc7", arc7), ("PC6", pc6)):
        hours = 0.0
        for a, b in zip(r.coords[:-1], r.coords[1:]):
            n = 4000
            lat, lon = sphere.intermediate(a[0], a[1], b[0], b[1], (np.arange(n) + 0.5) / n)
            i = np.abs(ds.lat.values[:, None] - lat).argmin(0)
            j = np.abs(ds.lon.values[:, None] - lon).argmin(0)
            hours += haversine_km(a[0], a[1], b[0], b[1]) / n * np.sum(1 / (knots[i, j] * KN))
        s = r.with_ice_speed(ice_speed(ds, cls, 12, stage_thickness="upper")).summary()
        assert s["time_h"] == pytest.approx(hours, rel=0.02)
        assert s["time_h"] > r.length / (12 * KN)  # slower than open water
