"""`seaway route --snap [--snap-km KM]`: ends moved together into water that joins them, at most
--snap-km (20 km by default), the ends asked for and used in every output; on a synthetic
SIGRID-3 chart of the AARI winter shape (a pocket of young ice beside the start) and on the real
CIS and NSIDC charts. Expected points: 4-connected bodies of usable pixels (scipy.ndimage.label)
and great-circle distances by pyproj's Geod on the engine's sphere."""

import json
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from seaway.cli import main

pytest.importorskip("pyogrio")
shapely = pytest.importorskip("shapely")
ndimage = pytest.importorskip("scipy.ndimage")
pyproj = pytest.importorskip("pyproj")
from seaway.ice import chart_impact  # noqa: E402
from seaway.ice.grids import latlon_grid  # noqa: E402
from seaway.ice.sigrid import read_sigrid3  # noqa: E402
from support.sigrid import write_chart  # noqa: E402

pytestmark = pytest.mark.cli
GEOD = pyproj.Geod(a=6371008.8, b=6371008.8)
CIS = ("ice_charts_sigrid3", "cis_eastern_arctic", "cis_SGRDREA_20201102T.gpkg")
NSIDC = ("sea_ice_concentration", "seaice_conc_daily_nh_20211231_f17_v04r00.nc")


@pytest.fixture(scope="module")
def pocket(tmp_path_factory):
    """Thick first-year ice (SA 93: closed to Arc5) at 60-61.8 E around a pocket of young ice
    (SA 83) at 60.9-61.1 E, 72.9-73.1 N; open water east of 61.8 E with an island at 69.3-69.7
    E, 72.8-73.2 N."""
    box, thick = shapely.box, {"POLY_TYPE": "I", "CT": "92", "SA": "93", "FA": "05"}
    water = {"POLY_TYPE": "W", "CT": "00"}
    rows = [
        (box(60, 70, 60.9, 76), thick),
        (box(61.1, 70, 61.8, 76), thick),
        (box(60.9, 70, 61.1, 72.9), thick),
        (box(60.9, 73.1, 61.1, 76), thick),
        (box(60.9, 72.9, 61.1, 73.1), {"POLY_TYPE": "I", "CT": "92", "SA": "83", "FA": "04"}),
        (box(61.8, 70, 69.3, 76), water),
        (box(69.7, 70, 80, 76), water),
        (box(69.3, 70, 69.7, 72.8), water),
        (box(69.3, 73.2, 69.7, 76), water),
        (box(69.3, 72.8, 69.7, 73.2), {"POLY_TYPE": "L"}),
    ]
    path = write_chart(tmp_path_factory.mktemp("pocket") / "pocket.shp", rows)
    return str(path), read_sigrid3(str(path), latlon_grid(70, 76, 60, 80, 0.1))


def joint_reference(ds, vessel, ends):
    """(point, km) of each end in the body of usable water that moves them least in total."""
    usable = np.isfinite(chart_impact(ds, vessel).values) & ~ds.land.values
    labels, n = ndimage.label(usable)
    best = None
    for k in range(1, n + 1):
        rr, cc = np.nonzero(labels == k)
        lat, lon = ds.lat.values[rr], ds.lon.values[cc]
        moves = []
        for p in ends:
            d = GEOD.inv(np.full(lat.size, p[1]), np.full(lat.size, p[0]), lon, lat)[2] / 1000
            i = int(np.argmin(d))
            moves.append(((float(lat[i]), float(lon[i])), float(d[i])))
        if best is None or moves[0][1] + moves[1][1] < best[0][1] + best[1][1]:
            best = moves
    return best


def test_snapped_ends_join_in_one_water_and_every_output_names_both(pocket, tmp_path, capsys):
    path, ds = pocket
    (s, s_km), (e, e_km) = joint_reference(ds, "Arc5", [(73.05, 60.55), (73.05, 69.55)])
    assert s[1] > 61.8 and 40 < s_km < 45  # into the open water, not the pocket 15 km away
    args = [
        "route",
        path,
        "--from",
        "73.05,60.55",
        "--to",
        "73.05,69.55",
        "--vessel",
        "Arc5",
        "--grid",
        "70,76,60,80,0.1",
        "--no-smooth",
    ]
    assert main(args + ["-q"]) == 1  # without --snap: both named, with the points they would take
    err = capsys.readouterr().err
    assert (
        f"start 73.05,60.55 is on an impassable pixel (ice an Arc5 ship may not enter: thick "
        f"first-year ice (WMO stage 93, 10/10), total concentration 10/10); the nearest point "
        f"the ship may use is {s[0]:.4f},{s[1]:.4f}, {s_km:.1f} km away: give it, or pass --snap"
    ) in err
    assert (
        f"end 73.05,69.55 is on an impassable pixel (land); the nearest point the ship may use is "
        f"{e[0]:.4f},{e[1]:.4f}, {e_km:.1f} km away" in err
    )
    assert main(args + ["--snap", "-q"]) == 1  # the start would move 42 km: more than 20
    assert (
        f"{s_km:.1f} km away, farther than --snap-km 20: give a point in water the ship may use, "
        f"or --snap-km {np.ceil(s_km):.0f} to move the start there"
    ) in capsys.readouterr().err
    outs = [tmp_path / f"r.{x}" for x in ("geojson", "gpx", "rtz", "csv", "html")]
    pytest.importorskip("folium")
    code = main(args + ["--snap", "--snap-km", "50", "-q"] + [a for o in outs for a in ("--out", str(o))])
    out, err = capsys.readouterr()
    assert code == 0, err
    moved = (
        f"start 73.05,60.55 is on an impassable pixel (ice an Arc5 ship may not enter: thick "
        f"first-year ice (WMO stage 93, 10/10), total concentration 10/10): moved {s_km:.1f} km to "
        f"{s[0]:.4f},{s[1]:.4f} (--snap, at most 50 km)"
    )
    assert moved in err and f"moved {e_km:.1f} km to {e[0]:.4f},{e[1]:.4f}" in err
    assert "requested 73-03.00N 060-33.00E -> 73-03.00N 069-33.00E" in out and f"assumed: {moved}" in out
    props = json.loads(outs[0].read_text())["properties"]
    assert props["requested_start"] == [73.05, 60.55] and props["start"] == pytest.approx(list(s))
    assert props["requested_end"] == [73.05, 69.55] and props["end"] == pytest.approx(list(e))
    assert moved in props["assumptions"]
    desc = ET.parse(outs[1]).getroot().find(".//{http://www.topografix.com/GPX/1/1}desc").text
    assert f"start {s[0]:.5f},{s[1]:.5f} (requested 73.05,60.55)" in desc and moved in desc
    ext = ET.parse(outs[2]).getroot().find(".//{http://www.cirm.org/RTZ/1/0}extension")
    assert (
        ext.get("manufacturer") == "seaway"
        and f"end {e[0]:.5f},{e[1]:.5f} (requested 73.05,69.55)" in ext.text
    )
    head = [x for x in outs[3].read_text().splitlines() if x.startswith("#")]
    assert head[1].startswith("# speed in ice: Andreeva 2021")  # every ice route is timed
    assert head[2:4] == [
        f"# start {s[0]:.5f},{s[1]:.5f} (requested 73.05,60.55)",
        f"# end {e[0]:.5f},{e[1]:.5f} (requested 73.05,69.55)",
    ]
    popups = [json.loads(p) for p in re.findall(r'\.bindPopup\(("(?:[^"\\]|\\.)*")', outs[4].read_text())]
    assert popups[0].startswith("<b>waypoint 1: start</b>")
    assert "requested 73&deg;03.0'N 060&deg;33.0'E" in popups[0] and moved in popups[0]
    assert popups[-1].startswith(f"<b>waypoint {len(popups)}: end</b>")
    assert "requested 73&deg;03.0'N 069&deg;33.0'E" in popups[-1]


@pytest.mark.needs_data(*CIS)
def test_a_start_on_real_land_moves_into_the_water_of_the_end(shared_data, tmp_path, capsys):
    """CIS, 2 November 2020: a start on the Greenland coast near Sisimiut (land, POLY_TYPE L)
    moves to the nearest water joined to the end in Baffin Bay."""
    path = str(shared_data.joinpath(*CIS))
    ds = read_sigrid3(path, latlon_grid(65, 74, -62, -50, 0.05))
    (s, s_km), _ = joint_reference(ds, "Arc7", [(67.0, -53.7), (72.0, -58.0)])
    out = tmp_path / "r.geojson"
    code = main(
        [
            "route",
            path,
            "--from",
            "67.0,-53.7",
            "--to",
            "72.0,-58.0",
            "--vessel",
            "Arc7",
            "--grid",
            "65,74,-62,-50,0.05",
            "--land",
            "chart",  # the reference is the chart's own land
            "--snap",
            "--out",
            str(out),
            "-q",
        ]
    )
    err = capsys.readouterr().err
    assert code == 0, err
    assert (
        f"start 67,-53.7 is on an impassable pixel (land): moved {s_km:.1f} km to "
        f"{s[0]:.4f},{s[1]:.4f} (--snap, at most 20 km)"
    ) in err
    props = json.loads(out.read_text())["properties"]
    assert props["requested_start"] == [67.0, -53.7] and props["start"] == pytest.approx(list(s))


@pytest.mark.needs_data(*NSIDC)
def test_the_issue_case_on_nsidc_is_refused_naming_the_distance(shared_data, capsys):
    """NSIDC G02202, 31 December 2021 (EPSG:3411): Baydaratskaya Bay and the Gulf of Ob lie in ice
    an Arc5 ship may not enter (thick first-year, assumed); the nearest usable water is
    hundreds of km away, so --snap refuses instead of printing a route from somewhere else."""
    code = main(
        [
            "route",
            str(shared_data.joinpath(*NSIDC)),
            "--vessel",
            "Arc5",
            "--from",
            "70.3,66.0",
            "--to",
            "72.9,74.0",
            "--snap",
            "-q",
        ]
    )
    err = capsys.readouterr().err
    assert code == 1
    m = re.search(
        r"start 70.3,66 is on an impassable pixel \(ice an Arc5 ship may not enter: thick "
        r"first-year ice \(WMO stage 93\), total concentration 10/10\); the nearest point "
        r"the ship may use is ([\d.]+),([\d.]+), ([\d.]+) km away, farther than --snap-km 20",
        err,
    )
    assert m, err
    lat, lon, km = map(float, m.groups())
    assert km == pytest.approx(GEOD.inv(66.0, 70.3, lon, lat)[2] / 1000, abs=0.05) and km > 400
