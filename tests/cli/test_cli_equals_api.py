"""The command line is a shell over the library: on each kind of real file in ../shared/data,
``seaway route`` / ``seaway season`` and seaway.open_chart / open_season / open_forecast give the
same route (vertices, cost, length, time and the assumptions recorded)."""

from __future__ import annotations

import json

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway.cli import main

pytestmark = pytest.mark.cli

DMI = ("ice_charts_sigrid3", "dmi_greenland")
CIS = ("ice_charts_sigrid3", "cis_eastern_arctic", "cis_SGRDREA_20201102T.gpkg")
NSIDC = ("sea_ice_concentration", "seaice_conc_daily_nh_20211231_f17_v04r00.nc")
ROMS = ("ocean_model", "metno_ROMS_Arctic20_1to5Feb_2016.nc")
ETOPO = ("bathymetry", "etopo5_arctic_60N.nc")


def _cli(tmp_path, *args):
    out = tmp_path / "cli.geojson"
    assert main([*args, "--out", str(out), "-q"]) == 0
    return json.loads(out.read_text())


def _same(feature, r):
    """The CLI's GeoJSON and the API's Route are one route."""
    api = json.loads(seaway.export.render(r, "geojson"))
    np.testing.assert_allclose(feature["geometry"]["coordinates"], api["geometry"]["coordinates"], atol=1e-9)
    for key in ("cost", "length", "time_h", "assumptions", "start", "end", "requested_start"):
        assert feature["properties"].get(key) == api["properties"].get(key), key


def _dmi(shared_data, day):
    return str(next(shared_data.joinpath(*DMI).glob(f"{day}*.shp")))


@pytest.mark.needs_data(*DMI)
def test_sigrid3_shapefile(shared_data, tmp_path):
    path, a, b = _dmi(shared_data, "20130410"), (59.5, -44.0), (60.5, -42.0)
    cli = _cli(
        tmp_path, "route", path, "--from", "59.5,-44", "--to", "60.5,-42", "--vessel", "PC6", "--speed", "12"
    )
    r = seaway.open_chart(path, vessel="PC6", ends=(a, b)).route(a, b, speed_kn=12)
    _same(cli, r)
    assert "PC6" in r.notes[-1] and r.length > 100


@pytest.mark.needs_data(*CIS)
def test_sigrid3_geopackage_with_a_grid_and_snap(shared_data, tmp_path):
    path, a, b = str(shared_data.joinpath(*CIS)), (67.0, -53.7), (72.0, -58.0)
    grid = (65, 74, -62, -50, 0.05)
    cli = _cli(
        tmp_path,
        "route",
        path,
        "--from",
        "67,-53.7",
        "--to",
        "72,-58",
        "--grid",
        "65,74,-62,-50,0.05",
        "--snap",
    )
    r = seaway.open_chart(path, grid=grid).route(a, b, snap_km=20)
    _same(cli, r)
    assert r.requested[0] == a and any(
        n.startswith("start 67,-53.7 is on an impassable pixel (land)") for n in r.notes
    )


@pytest.mark.needs_data(*NSIDC)
def test_nsidc_projected_concentration(shared_data, tmp_path):
    path, a, b = str(shared_data.joinpath(*NSIDC)), (70.3, 66.0), (72.9, 74.0)
    cli = _cli(
        tmp_path, "route", path, "--vessel", "Arc7", "--from", "70.3,66", "--to", "72.9,74", "--escort"
    )
    chart = seaway.open_chart(path, vessel="Arc7")
    r = chart.route(a, b, escort=True)
    _same(cli, r)
    assert chart.crs is not None and "3411" in chart.crs.to_string()
    assert any("thick first-year ice (WMO stage 93), an assumption" in n for n in r.notes)


@pytest.mark.needs_data(*ROMS)
def test_roms_ice_chart_and_its_currents(shared_data, tmp_path):
    """The ROMS file as an ice chart (aice as concentration, its own polar stereographic grid),
    and as a forecast of currents."""
    path = str(shared_data.joinpath(*ROMS))
    a, b = (75.0, 20.0), (77.0, 40.0)
    cli = _cli(
        tmp_path, "route", path, "--variable", "aice", "--vessel", "Arc7", "--from", "75,20", "--to", "77,40"
    )
    r = seaway.open_chart(path, variable="aice", vessel="Arc7").route(a, b)
    _same(cli, r)
    ends = ["--depart", "2016-02-01T12:00", "--from", "70.5,20", "--to", "76,45"]
    cli = _cli(tmp_path, "route", "--forecast", path, *ends)
    fc = seaway.open_forecast(path).route((70.5, 20.0), (76.0, 45.0), depart="2016-02-01T12:00")
    _same(cli, fc)
    assert fc.cost == pytest.approx(cli["properties"]["time_h"], rel=1e-12)


@pytest.mark.needs_data(*ETOPO)
def test_depth_and_draft_on_the_builtin_chart(shared_data, tmp_path):
    depth = str(shared_data.joinpath(*ETOPO))
    a, b = (70.3, 58.5), (72.5, 66.0)
    cli = _cli(
        tmp_path,
        "route",
        "kara",
        "--from",
        "70.3,58.5",
        "--to",
        "72.5,66",
        "--depth",
        depth,
        "--draft",
        "9",
        "--snap",
    )
    chart = seaway.open_chart("kara", depth=depth)
    r = chart.route(a, b, draft_m=9, snap_km=20)
    _same(cli, r)
    assert any(n.startswith("depth from") for n in r.notes) and chart.depth is not None


@pytest.mark.needs_data(*DMI)
def test_a_season_of_sigrid3_charts(shared_data, tmp_path):
    charts = {"2013-04-10": _dmi(shared_data, "20130410"), "2013-04-11": _dmi(shared_data, "20130722")}
    a, b = (59.5, -44.0), (60.5, -42.0)
    dated = [f"{d}={p}" for d, p in charts.items()]
    cli = _cli(
        tmp_path, "season", *dated, "--from", "59.5,-44", "--to", "60.5,-42", "--vessel", "PC6", "--snap"
    )
    season = seaway.open_season(charts, ends=(a, b))
    r = season.route(a, b, vessel="PC6", snap_km=20)
    _same(cli, r)
    assert r.stats.voyage is not None and r.cost == pytest.approx(cli["properties"]["time_h"], rel=1e-12)


def _banded(tmp_path):
    """70-76 N, 60-76 E: open water (stage 55) with a band of thin first-year ice (87) across
    72.5-73.5 N at 10/10, but 7/10 in a gap at 73-74 E."""
    lat, lon = np.linspace(76.0, 70.0, 61), np.linspace(60.0, 76.0, 81)
    band = (lat[:, None] >= 72.5) & (lat[:, None] <= 73.5) & np.ones((1, 81), bool)
    gap = band & (lon[None, :] >= 73.0) & (lon[None, :] <= 74.0)
    stage = np.where(band, 87.0, 55.0)
    conc = np.where(gap, 7.0, np.where(band, 10.0, 0.0))
    ds = xr.Dataset(
        {
            "stage_of_development": (("lat", "lon"), stage),
            "sea_ice_concentration": (("lat", "lon"), conc, {"units": "0.1"}),
            "land": (("lat", "lon"), np.zeros((61, 81), bool)),
        },
        coords={"lat": lat, "lon": lon},
    )
    path = tmp_path / "banded.nc"
    ds.to_netcdf(path)
    return str(path), conc, lat, lon


def test_concentration_limit_flag(tmp_path):
    """--concentration-limit closes ice over the class's limit (Arc7: over 8/10) as
    OpenChart.route(concentration_limit=True) does: the route crosses the band only at its 7/10
    gap, and says so; without it the route crosses the 10/10 ice."""
    path, conc, lat, lon = _banded(tmp_path)
    a, b = (75.0, 62.0), (71.0, 62.0)
    cli = _cli(
        tmp_path,
        "route",
        path,
        "--vessel",
        "Arc7",
        "--from",
        "75,62",
        "--to",
        "71,62",
        "--concentration-limit",
    )
    chart = seaway.open_chart(path, vessel="Arc7")
    r = chart.route(a, b, concentration_limit=True)
    _same(cli, r)
    free = chart.route(a, b)
    steps, free_steps = (chart.route(a, b, concentration_limit=c, smooth=False).pixels for c in (True, False))
    assert (
        conc[steps[:, 0], steps[:, 1]].max() == 7.0 and conc[free_steps[:, 0], free_steps[:, 1]].max() == 10.0
    )
    assert r.length > free.length * 1.5  # the detour to the gap, 11 degrees of longitude east
    said = "ice over Arc7's concentration limit for independent navigation (8/10 total concentration"
    assert any(n.startswith(said) for n in r.notes) and not any(n.startswith(said) for n in free.notes)
    with pytest.raises(
        seaway.SeawayError,
        match=r"on an impassable pixel \(total concentration 10/10, over Arc7's limit for independent navigation \(8/10; concentration_limit\)\)",
    ):
        chart.route((73.0, 62.0), b, concentration_limit=True)
