"""The built-in charts (seaway.charts) and the `python -m seaway demo` command."""

import hashlib
import json
import re
import subprocess
import sys

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway import samples as charts
from seaway.cli import main

INF = np.inf
# Paper 000, Table 2 (Arc7 and stronger) and Table 3 (Arc5), transcribed independently of
# charts.ICE_IMPACT: WMO stage code -> impact u.
PAPER_TABLES = {
    "Arc7": {55: 2, 81: 3, 82: 5, 84: 8, 83: 10, 85: 13, 87: 15, 88: 15, 89: 15, 86: 20, 91: 25, 93: 30},
    "Arc5": {55: 1, 81: 3, 82: 5, 84: 10, 83: 15, 85: 25, 87: 30, 88: 30, 89: 30, 86: INF, 91: INF, 93: INF},
}
CHART_STAGES = {55, 81, 82, 84, 85, 86, 87, 91, 93}


@pytest.fixture(scope="module")
def kara():
    return charts.kara_sea()


def _digest(ds):
    h = hashlib.sha256()
    for name in sorted(ds.variables):
        h.update(name.encode())
        h.update(np.ascontiguousarray(ds[name].values).tobytes())
    return h.hexdigest()


def _at(ds, lat, lon):
    return ds.sel(lat=lat, lon=lon, method="nearest")


def test_kara_sea_grid_and_cf_attributes(kara):
    assert dict(kara.sizes) == {"lat": 1900, "lon": 2300}
    lat, lon = kara.lat.values, kara.lon.values
    assert np.all(np.diff(lat) < 0) and np.all(np.diff(lon) > 0)  # north to south, west to east
    np.testing.assert_allclose(np.diff(lat), -14 / 1900, rtol=1e-9)
    np.testing.assert_allclose(
        [lat[0], lat[-1], lon[0], lon[-1]], [82 - 7 / 1900, 68 + 7 / 1900, 50 + 30 / 2300, 110 - 30 / 2300]
    )
    assert abs(lat[0] - lat[1]) * charts.KM_PER_DEG == pytest.approx(0.8190, abs=1e-3)
    assert (kara.lat.attrs["standard_name"], kara.lat.attrs["units"]) == ("latitude", "degrees_north")
    assert (kara.lon.attrs["standard_name"], kara.lon.attrs["units"]) == ("longitude", "degrees_east")
    expected = {
        "land": ("land_binary_mask", "1"),
        "sea_ice_concentration": ("sea_ice_area_fraction", "0.1"),
        "ice_thickness": ("sea_ice_thickness", "m"),
    }
    for name, (std, units) in expected.items():
        assert (kara[name].attrs["standard_name"], kara[name].attrs["units"]) == (std, units)
    stage = kara.stage_of_development.attrs  # no CF standard name exists: flags instead
    assert stage["units"] == "1"
    assert sorted(stage["flag_values"].tolist()) == sorted(charts.STAGES)
    assert len(stage["flag_meanings"].split()) == len(charts.STAGES)
    assert "synthetic" in kara.attrs["title"].lower()
    assert "synthetic" in kara.attrs["source"] and "GLOBE" in kara.attrs["source"]
    assert kara.land.dtype == bool and kara.ice_thickness.dtype == np.float32


def test_kara_sea_is_deterministic_and_returns_copies(kara):
    first = _digest(kara)
    again = charts.kara_sea()
    again["ice_thickness"].values[:] = -1.0  # must not reach the cache
    assert _digest(charts.kara_sea()) == first
    assert again is not kara


def test_land_is_the_globe_mask_at_pixel_centres(kara):
    from global_land_mask import globe

    expected = globe.is_land(kara.lat.values[:, None], kara.lon.values[None, :])
    np.testing.assert_array_equal(kara.land.values, expected)
    assert 0.35 < float(kara.land.mean()) < 0.45  # Taymyr, Yamal, Gydan, Novaya Zemlya ...


@pytest.mark.parametrize(
    "lat, lon, is_land",
    [
        (74.0, 56.0, True),  # Novaya Zemlya, northern island
        (70.0, 70.0, True),  # Yamal peninsula
        (73.0, 95.0, True),  # Taymyr
        (75.5, 70.0, False),  # open Kara Sea
        (79.0, 75.0, False),  # northern Kara Sea
        (71.0, 50.5, False),  # south-east Barents Sea
    ],
)
def test_known_points(kara, lat, lon, is_land):
    p = _at(kara, lat, lon)
    assert bool(p.land) is is_land
    assert bool(np.isnan(p.stage_of_development)) is is_land
    assert bool(np.isnan(p.ice_thickness)) is is_land


def test_stage_concentration_and_thickness_agree(kara):
    land = kara.land.values
    stage = kara.stage_of_development.values
    conc = kara.sea_ice_concentration.values
    h = kara.ice_thickness.values
    assert np.all(np.isnan(stage[land]) & np.isnan(conc[land]) & np.isnan(h[land]))
    stage, conc, h = stage[~land], conc[~land], h[~land]
    assert set(np.unique(stage).astype(int).tolist()) == CHART_STAGES
    assert np.array_equal(conc, np.round(conc)) and conc.min() == 0 and conc.max() == 10
    for code in CHART_STAGES:
        lo, hi = charts.STAGES[code][1]
        hh = h[stage == code]
        if code == 55:
            assert np.all(hh == 0) and np.all(conc[stage == code] == 0)
        else:
            assert np.all((hh >= lo - 1e-6) & (hh < hi)), code
            assert np.all(conc[stage == code] > 0), code
    assert h.max() < 2.0


def test_ice_looks_like_a_winter_kara_sea(kara):
    water = ~kara.land.values
    stage = kara.stage_of_development.values
    h = kara.ice_thickness.values
    lat, lon = np.meshgrid(kara.lat.values, kara.lon.values, indexing="ij")
    # Fast ice: water pixels next to land are 10/10 first-year ice (mostly thick).
    landp = np.pad(~water, 1, constant_values=False)
    shore = water & (landp[:-2, 1:-1] | landp[2:, 1:-1] | landp[1:-1, :-2] | landp[1:-1, 2:])
    kara_side = shore & (lon > 60)
    assert np.mean(np.isin(stage[kara_side], (86, 91, 93))) > 0.9
    assert np.mean(stage[kara_side] == 93) > 0.5
    assert np.all(kara.sea_ice_concentration.values[kara_side & np.isin(stage, (91, 93))] >= 8)
    # Thicker ice to the north-east (boxes of open sea, away from the fast ice).
    ne = water & (lat > 77) & (lat < 80) & (lon > 80) & (lon < 95)
    sw = water & (lat > 72) & (lat < 75) & (lon > 60) & (lon < 70)
    assert np.mean(h[ne]) > np.mean(h[sw]) + 0.3
    # Flaw polynyas: open water, new ice and nilas in the Kara Sea proper, not only the Barents.
    kara_sea_proper = water & (lon > 70)
    for code in (55, 81, 82):
        assert np.count_nonzero(kara_sea_proper & (stage == code)) > 1000, code


def test_smaller_charts_cover_the_same_extent():
    small = charts.kara_sea((190, 230))
    assert dict(small.sizes) == {"lat": 190, "lon": 230}
    assert float(small.lat[0]) == pytest.approx(82 - 7 / 190)
    assert bool(_at(small, 74.0, 56.0).land) and not bool(_at(small, 75.5, 70.0).land)
    with pytest.raises(ValueError, match="shape"):
        charts.kara_sea((1, 10))
    with pytest.raises(ValueError, match="shape"):
        charts.kara_sea(100)


@pytest.mark.parametrize("ice_class", ["Arc7", "Arc5"])
def test_ice_impact_is_paper_000_table(ice_class):
    table = PAPER_TABLES[ice_class]
    codes = np.array(sorted(table), dtype=float)
    u = charts.ice_impact(codes, ice_class)
    assert u.dtype == np.float64
    assert u.tolist() == [table[c] for c in sorted(table)]


def test_ice_impact_classes_and_inputs():
    codes = np.array([[55, 86], [91, 93]])
    np.testing.assert_array_equal(charts.ice_impact(codes, "Arc5"), [[1, INF], [INF, INF]])
    for stronger in ("Arc8", "Arc9", "arc9"):
        np.testing.assert_array_equal(charts.ice_impact(codes, stronger), [[2, 20], [25, 30]])
    assert charts.ice_impact(np.array([np.nan, 82.0])).tolist() == [INF, 5.0]
    assert charts.ice_impact(np.uint8(84), "Arc5") == 10.0
    da = xr.DataArray(codes.astype(float), dims=("lat", "lon"), coords={"lat": [71, 70], "lon": [60, 61]})
    out = charts.ice_impact(da, "Arc7")
    assert isinstance(out, xr.DataArray) and out.attrs["ice_class"] == "Arc7"
    assert out.values.tolist() == [[2, 20], [25, 30]] and out.lat.values.tolist() == [71, 70]
    # Every class of seaway.ice.classes now has a table (derived for all but Arc5/Arc7-9).
    with pytest.raises(ValueError, match=r"Arc5.*Arc7.*Arc8.*Arc9"):
        charts.ice_impact(codes, "Arc10")
    with pytest.raises(ValueError, match="ice_class"):
        charts.ice_impact(codes, "PC8")
    with pytest.raises(ValueError, match=r"95\.0"):
        charts.ice_impact(np.array([55, 95]), "Arc7")


def test_kara_sea_costs_route_without_a_land_mask(kara):
    """NaN stages on land become inf impact, so the stage raster alone keeps a route at sea."""
    u = charts.ice_impact(
        kara.stage_of_development.isel(lat=slice(None, None, 10), lon=slice(None, None, 10))
    )
    r = seaway.route(u, (75.5, 70.0), (79.0, 75.0), neighbourhood=3)
    land = kara.land.values[::10, ::10]
    assert not land[r.pixels[:, 0], r.pixels[:, 1]].any()
    assert 2.0 * r.length <= r.cost <= 30.0 * r.length


def test_synthetic_sea():
    a = charts.synthetic_sea()
    assert a.shape == (1900, 2300) and a.dtype == np.float64
    water = np.isfinite(a)
    assert np.all(np.isinf(a[~water]) & (a[~water] > 0))
    assert abs((1 - water.mean()) - 0.3) < 0.05
    assert a[water].min() >= 1.0 and a[water].max() <= 30.0
    assert 0.05 < np.mean(a[water] < 2.0) < 0.4  # open water costs 1-2
    assert np.array_equal(a, charts.synthetic_sea())
    assert not np.array_equal(a, charts.synthetic_sea(seed=1))
    (r0, c0), (r1, c1) = charts.SYNTHETIC_START, charts.SYNTHETIC_END
    assert r0 > 0.9 * 1900 and c0 < 0.1 * 2300 and r1 < 0.1 * 1900 and c1 > 0.9 * 2300
    assert water[charts.SYNTHETIC_START] and water[charts.SYNTHETIC_END]
    r = seaway.route(a, charts.SYNTHETIC_START, charts.SYNTHETIC_END, neighbourhood=3)
    assert np.isfinite(r.cost) and r.cost >= r.length


@pytest.mark.parametrize(
    "shape, land_fraction, seed", [((190, 230), 0.3, 0), ((100, 120), 0.5, 7), ((300, 200), 0.0, 3)]
)
def test_synthetic_sea_other_shapes_stay_connected(shape, land_fraction, seed):
    a = charts.synthetic_sea(shape, land_fraction=land_fraction, seed=seed)
    assert a.shape == shape
    assert abs(np.mean(np.isinf(a)) - land_fraction) < 0.01
    start, end = charts.synthetic_endpoints(shape)
    assert seaway.route(a, start, end, neighbourhood=3).cost > 0


def _run_demo(*args):
    return subprocess.run(
        [sys.executable, "-m", "seaway", "demo", *args], capture_output=True, text=True, timeout=120
    )


@pytest.mark.cli
def test_demo_arc7(kara, tmp_path):
    out = tmp_path / "route.geojson"
    done = _run_demo("--out", str(out))
    assert done.returncode == 0, done.stderr
    assert done.stderr == ""
    text = done.stdout
    num = r"([0-9.]+)"
    cost = float(re.search(rf"route cost: +{num}", text).group(1))
    km, nm = map(float, re.search(rf"length: +{num} km = {num} nm", text).groups())
    waypoints = int(re.search(r"waypoints: +(\d+)", text).group(1))
    settled = int(re.search(r"(\d+) pixels settled", text).group(1))
    first = tuple(map(float, re.search(rf"first: +{num} N {num} E", text).groups()))
    last = tuple(map(float, re.search(rf"last: +{num} N {num} E", text).groups()))
    assert "1900 x 2300 pixels" in text and "Arc7" in text and "GLOBE" in text
    assert cost > 0 and km > 1100 and nm == pytest.approx(km / 1.852, abs=0.06)
    assert waypoints > 100 and settled > waypoints
    assert first == pytest.approx((70.3, 58.5), abs=0.05) and last == pytest.approx((77.7, 104.0), abs=0.05)
    # The same route through the API gives the printed numbers.
    u = charts.ice_impact(kara.stage_of_development, "Arc7")
    r = seaway.route(u, first, last, land=kara.land)
    assert cost == pytest.approx(r.cost, abs=0.05) and km == pytest.approx(r.length, abs=0.05)
    assert waypoints == len(r.waypoint_index)  # what every export gives
    feature = json.loads(out.read_text())
    assert feature["geometry"]["type"] == "LineString"
    assert len(feature["geometry"]["coordinates"]) == waypoints
    assert feature["geometry"]["coordinates"][0] == pytest.approx([first[1], first[0]], abs=1e-4)
    assert feature["properties"]["ice_class"] == "Arc7"


@pytest.mark.cli
def test_demo_arc5_has_no_route():
    """Arc5 may not enter first-year ice (paper 000, Table 3): the water at the Vilkitsky Strait
    is closed to it, and the nearest water it may use joined to the Kara Gate is 1195 km away."""
    done = _run_demo("--ice-class", "Arc5")
    assert done.returncode == 1 and done.stdout == ""
    message = done.stderr.strip()
    assert "\n" not in message
    assert message.startswith("seaway demo: error: end 77.7,104 is on an impassable pixel")
    assert (
        "the nearest point the ship may use is 74.2963,60.5783, 1195.2 km away, farther than --snap-km 30"
        in message
    )


@pytest.mark.cli
def test_demo_in_process(capsys):
    assert main(["demo", "--ice-class", "Arc9", "--neighbourhood", "3", "--method", "dijkstra"]) == 0
    text = capsys.readouterr().out
    assert "vessel class: Arc9" in text and "dijkstra, 3x3 neighbourhood" in text


@pytest.mark.cli
@pytest.mark.parametrize(
    "args",
    [["demo", "--neighbourhood", "4"], ["demo", "--ice-class", "Arc10"], ["demo", "--method", "bfs"], []],
)
def test_demo_bad_arguments_exit_2(args, capsys):
    with pytest.raises(SystemExit) as exit_info:
        main(args)
    assert exit_info.value.code == 2
    assert "error" in capsys.readouterr().err
