"""Form of ice (issue 19): fast ice as an ice type with a stated, editable stage; bergy water
and open water freely navigable; on the real CIS and DMI charts and on a synthetic chart shaped
like AARI's winter pan-Arctic charts (most polygons FA 08, SA 99, CT 92)."""

import numpy as np
import pytest

import seaway
from seaway import export
from seaway._core import haversine_km
from seaway.ice import chart_impact
from seaway.ice.forms import check_fast_ice
from seaway.ice.impact import governing_stage
from seaway.icenav import summary

pytest.importorskip("pyogrio")
shapely = pytest.importorskip("shapely")
pytest.importorskip("rasterio")
from seaway.ice.grids import latlon_grid  # noqa: E402
from seaway.ice.sigrid import read_sigrid3  # noqa: E402
from support.sigrid import write_chart  # noqa: E402

CIS = ("ice_charts_sigrid3", "cis_eastern_arctic", "cis_SGRDREA_20201102T.gpkg")
DMI = ("ice_charts_sigrid3", "dmi_greenland", "201405011000_SouthWest_RIC.shp")
START, END = (73.0, 61.0), (73.0, 79.0)  # water at both ends, fast ice between


def _write(path, rows):
    return write_chart(path, rows)


def _dense_km(route, inside, n=400):
    """km of the route's vertices-to-vertices lines (lat/lon linear: short steps) where
    inside(lat, lon), by n points per step: the reference for summarize()."""
    total = 0.0
    c = route.coords
    for a, b in zip(c[:-1], c[1:]):
        t = (np.arange(n) + 0.5) / n
        lat, lon = a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])
        total += haversine_km(*a, *b) * inside(lat, lon).mean()
    return total


@pytest.fixture(scope="module")
def aari(tmp_path_factory):
    """AARI's winter shape: the Kara Sea between 63 E and 77 E fast ice of unknown stage (three
    polygons FA 08 SA 99 CT 92, as AARI codes it), a strip of thin first-year pack ice (SA 87,
    FA 04) north of it, open water at both ends."""
    fast = {"POLY_TYPE": "I", "CT": "92", "SA": "99", "FA": "08"}
    rows = [
        (shapely.box(60, 70, 63, 76), {"POLY_TYPE": "W", "CT": "00"}),
        (shapely.box(77, 70, 80, 76), {"POLY_TYPE": "W", "CT": "00"}),
        (shapely.box(63, 70, 68, 75), fast),
        (shapely.box(68, 70, 72, 75), fast),
        (shapely.box(72, 70, 77, 75), fast),
        (shapely.box(63, 75, 77, 76), {"POLY_TYPE": "I", "CT": "92", "SA": "87", "FA": "04"}),
    ]
    path = _write(tmp_path_factory.mktemp("aari") / "aari_winter.shp", rows)
    return str(path), read_sigrid3(str(path), latlon_grid(70, 76, 60, 80, 0.1))


def test_the_reader_keeps_the_form_codes_as_layers(aari):
    _, ds = aari
    at = ds.sel(lat=73, lon=70, method="nearest")
    assert float(at.FA) == 8 and float(at.SA) == 99 and float(at.CT) == 10
    assert "fast ice" in ds.FA.attrs["long_name"] and "fast_ice" in ds.FA.attrs["flag_meanings"]
    assert float(ds.sel(lat=75.5, lon=70, method="nearest").FA) == 4  # medium floes
    assert np.isnan(float(ds.sel(lat=73, lon=61, method="nearest").FA))  # water: no form


def test_fast_ice_of_unknown_stage_takes_the_stated_assumption(aari):
    _, ds = aari
    at = dict(lat=73, lon=70, method="nearest")
    nearby = governing_stage(ds)  # default: the thickest first-year stage on the grid
    assert float(nearby.sel(**at)) == 87
    (said,) = nearby.attrs["assumptions"]
    assert "fast ice of unknown stage (FA 08, SA 99)" in said
    assert "ASSUMED thin first-year ice (WMO 87), the thickest first-year stage" in said
    assert float(governing_stage(ds, fast_ice=93).sel(**at)) == 93
    assert np.isnan(float(governing_stage(ds, fast_ice="closed").sel(**at)))
    assert chart_impact(ds, "Arc7", fast_ice="closed").sel(**at) == np.inf
    assert float(chart_impact(ds, "Arc7").sel(**at)) == 15.0  # Table 2, thin first-year
    with pytest.raises(ValueError, match=r"fast_ice must be 'nearby', 'closed' or a WMO stage code"):
        check_fast_ice("open")


def test_arc7_crosses_fast_ice_directly_under_the_assumption_and_says_so(aari):
    _, ds = aari
    direct = seaway.route(chart_impact(ds, "Arc7"), START, END, land=ds.land)
    closed = seaway.route(chart_impact(ds, "Arc7", fast_ice="closed"), START, END, land=ds.land)
    straight = haversine_km(*START, *END)
    assert direct.coords[:, 0].max() < 75 <= closed.coords[:, 0].max()  # closed: round it by the pack
    assert direct.length < 1.2 * straight < closed.length  # 684 km (least ice, not the great circle)
    assert "ASSUMED thin first-year ice (WMO 87)" in direct.assumptions[0]
    assert "assumed: fast ice of unknown stage" in str(direct)
    s = summary.summarize(direct, ds)
    fast_km = s["by_stage"]["fast ice, thin first-year ice, assumed"]["distance"]
    assert fast_km == pytest.approx(_dense_km(direct, lambda lat, lon: (lon > 63) & (lon < 77)), rel=0.02)
    assert s["assumptions"] == direct.assumptions
    props = export.geojson(direct)["properties"]
    assert props["assumptions"] == list(direct.assumptions)


@pytest.mark.cli
def test_cli_fast_ice_switch_prints_the_assumption(aari, capsys):
    from seaway.cli import main

    path, _ = aari
    ends = ["--from", "73,61", "--to", "73,79", "--grid", "70,76,60,80,0.1", "--vessel", "Arc7"]
    assert main(["route", path, *ends, "--no-smooth"]) == 0
    out, err = capsys.readouterr()
    assert "assumed: fast ice of unknown stage (FA 08, SA 99)" in err and "(WMO 87)" in err
    assert "assumed: fast ice" in out  # on the route's own table too
    assert main(["route", path, *ends, "--fast-ice", "91", "--no-smooth"]) == 0
    assert "ASSUMED medium first-year ice (WMO 91), as you chose" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        main(["route", path, *ends, "--fast-ice", "thick"])
    assert "fast_ice must be 'nearby', 'closed' or a WMO stage code" in capsys.readouterr().err


@pytest.mark.needs_data(*CIS)
def test_cis_bergy_water_is_navigable_and_fast_ice_keeps_its_stage(shared_data):
    ds = read_sigrid3(str(shared_data.joinpath(*CIS)), latlon_grid(62, 84, -113, -22, (0.1, 0.25)))
    bergy = ds.free_water.values == 2  # the chart's CT 02 polygons: SA 98, FA 10
    assert bergy.sum() > 1000 and set(np.unique(ds.SA.values[bergy])) == {98.0}
    assert set(np.unique(ds.FA.values[bergy])) == {10.0}
    stage = governing_stage(ds)
    assert (stage.values[bergy] == 55).all()  # costed as ice free, not impassable glacier ice
    fast = ds.FA.values == 8
    assert fast.sum() > 1000 and set(np.unique(ds.SA.values[fast])) <= {84.0, 85.0, 87.0, 97.0}
    assert (stage.values[fast] == ds.SA.values[fast]).all()  # the chart's own stage
    assert not any("fast ice" in a for a in stage.attrs["assumptions"])  # nothing to assume
    assert "bergy water on" in stage.attrs["assumptions"][0]
    u = chart_impact(ds, "Arc7")
    r = seaway.route(u, (64, -57), (75, -70), land=ds.land)  # Davis Strait -> Baffin Bay
    s = summary.summarize(r, ds)
    assert "glacier ice" not in s["by_stage"] and s["by_stage"]["bergy water"]["distance"] > 300
    assert sum(v["distance"] for v in s["by_stage"].values()) == pytest.approx(r.length)


@pytest.mark.needs_data(*DMI)
def test_dmi_fast_ice_and_icebergs(shared_data):
    ds = read_sigrid3(str(shared_data.joinpath(*DMI)), latlon_grid(65, 71, -64, -50, 0.1))
    fast = ds.FA.values == 8  # DMI writes '8' without the leading zero: thin first-year (87)
    assert fast.sum() > 40 and set(np.unique(ds.SA.values[fast])) == {87.0}
    stage = governing_stage(ds)
    assert (stage.values[fast] == 87).all()
    assert not any("fast ice" in a for a in stage.attrs["assumptions"])  # the chart gives its stage
    bergs = (ds.FA.values == 10) & (ds.free_water.values == 0)  # icebergs at 1/10 or more (SA 98)
    berg_water = (ds.FA.values == 10) & (ds.free_water.values == 1)  # CT '1': < 1/10, open water
    assert (chart_impact(ds, "Arc7").values[berg_water] == 2).all()  # Table 2's ice free
    assert bergs.any() and (chart_impact(ds, "Arc7").values[bergs] == np.inf).all()
