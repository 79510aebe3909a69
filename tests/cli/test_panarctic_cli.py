"""Issue 10 part 1, the command line: `seaway route CHART.shp --from 70.4,58.6 --to 77.7,104.0
--vessel Arc7` on the synthetic pan-Arctic chart (tests/panarctic.py), in EPSG:4326 and in a
polar CRS, on the default regional grid; ends on land or in ice the class may not enter give a
message naming it, the nearest usable point and its distance, and --snap moves them there.

Expected values come from outside the code under test: the great-circle distance by pyproj's
Geod, paper 000's Table 2 value for the chart's ice, and the nearest reachable pixel from
scipy.ndimage.label (4-connected: the engine never steps across a corner of an impassable
pixel) and pyproj distances."""

import re
import subprocess
import sys

import numpy as np
import pytest

pytest.importorskip("antimeridian")
pytest.importorskip("pyogrio")
pyproj = pytest.importorskip("pyproj")
ndimage = pytest.importorskip("scipy.ndimage")

from seaway.ice import chart_impact  # noqa: E402
from seaway.ice.grids import latlon_grid  # noqa: E402
from seaway.ice.impact import TABLE_2  # noqa: E402
from seaway.ice.sigrid import read_sigrid3  # noqa: E402
from support import panarctic  # noqa: E402

GEOD = pyproj.Geod(a=6371008.8, b=6371008.8)  # the engine's sphere
KARA_GATE, VILKITSKY = (70.4, 58.6), (77.7, 104.0)


def run(*args):
    return subprocess.run(
        [sys.executable, "-m", "seaway", *args], capture_output=True, text=True, timeout=300
    )


@pytest.fixture(scope="module")
def charts(tmp_path_factory):
    """The chart in lon/lat (as AARI publishes) and the same polygons in EPSG:3413."""
    import pyogrio.raw
    import shapely

    d = tmp_path_factory.mktemp("panarctic")
    lonlat = d / "panarctic.shp"
    truth = panarctic.write(lonlat)
    _, _, attrs = panarctic.build()
    polar = d / "panarctic_3413.shp"
    names = ["POLY_TYPE", "CT", "CA", "SA", "CB", "SB"]
    data = [np.array([a[k] for a in attrs], dtype=object) for k in names]
    wkb = shapely.to_wkb([shapely.MultiPolygon(list(shapely.get_parts(g))) for g in truth])
    pyogrio.raw.write(str(polar), wkb, data, names, geometry_type="MultiPolygon", crs="EPSG:3413")
    return lonlat, polar


def km(a, b):
    return GEOD.inv(a[1], a[0], b[1], b[0])[2] / 1000.0


def table_value(stdout, label):
    m = re.search(rf"{label} ([\d.]+) km", stdout)
    return float(m.group(1))


@pytest.mark.cli
@pytest.mark.parametrize("which", ["lonlat", "polar"])
def test_route_kara_gate_to_vilkitsky_on_the_default_grid(charts, which, tmp_path):
    path = charts[0] if which == "lonlat" else charts[1]
    out = tmp_path / "r.geojson"
    done = run(  # --land chart: the synthetic chart's own land (tests/support/panarctic.py)
        "route",
        str(path),
        "--land",
        "chart",
        "--from",
        "70.4,58.6",
        "--to",
        "77.7,104.0",
        "--vessel",
        "Arc7",
        "--out",
        str(out),
    )
    assert done.returncode == 0, done.stderr
    # The default grid: 0.05 deg of latitude around the ends, widened by >= 300 km each side.
    m = re.search(r"grid: lat ([\d.]+)\.\.([\d.]+), lon ([\d.]+)\.\.([\d.]+) at 0.05 x", done.stderr)
    south, north, west, east = map(float, m.groups())
    assert south <= 70.4 - 300 / 111.2 and north >= 77.7 + 300 / 111.2
    assert west < 58.6 - 5 and east > 104.0 + 5 and east - west < 120
    import json

    feature = json.loads(out.read_text())
    coords = np.array(feature["geometry"]["coordinates"])  # lon, lat
    start, end = coords[0][::-1], coords[-1][::-1]
    assert km(start, KARA_GATE) < 5 and km(end, VILKITSKY) < 5  # the pixels holding the ends
    gc = km(start, end)
    length = feature["properties"]["length"]
    assert gc <= length <= 1.03 * gc  # the synthetic land leaves the great circle nearly open
    # Every pixel the route crosses is thin first-year ice (stage 87): Arc7's u = 15 per km.
    assert TABLE_2[87] == 15
    assert feature["properties"]["cost"] == pytest.approx(15 * length, rel=1e-6)


@pytest.fixture(scope="module")
def kara(charts):
    """The chart on the explicit grid the snapping tests use, and the usable pixels from the
    Kara Gate (4-connected component of the passable Arc7 pixels)."""
    grid = latlon_grid(66, 88, 40, 130, 0.1)
    ds = read_sigrid3(charts[0], grid)
    ok = np.isfinite(chart_impact(ds, "Arc7").values) & ~ds.land.values
    labels, _ = ndimage.label(ok)
    r = int(np.abs(ds.lat.values - 70.4).argmin())
    c = int(np.abs(ds.lon.values - 58.6).argmin())
    assert labels[r, c] > 0
    return ds, labels == labels[r, c]


def nearest_usable(ds, usable, p):
    rr, cc = np.nonzero(usable)
    lat, lon = ds.lat.values[rr], ds.lon.values[cc]
    d = GEOD.inv(np.full(lat.shape, p[1]), np.full(lat.shape, p[0]), lon, lat)[2] / 1000
    i = int(np.argmin(d))
    return (float(lat[i]), float(lon[i])), float(d[i])


GRID = ["--grid", "66,88,40,130,0.1"]


@pytest.mark.slow
@pytest.mark.cli
@pytest.mark.parametrize(
    "end, words",
    [
        ((69.0, 60.0), ["end 69,60 is on an impassable pixel (land)"]),
        (
            (84.5, 60.0),
            [
                "ice an Arc7 ship may not enter",
                "old ice (WMO stage 95, 9/10)",
                "glacier ice (WMO stage 98, 1/10)",
                "total concentration 10/10",
            ],
        ),
    ],
)
def test_an_end_on_land_or_in_forbidden_ice_is_named_with_the_nearest_usable_point(charts, kara, end, words):
    ds, usable = kara
    args = [
        "route",
        str(charts[0]),
        "--from",
        "70.4,58.6",
        "--to",
        f"{end[0]},{end[1]}",
        "--vessel",
        "Arc7",
        *GRID,
        "--no-smooth",
    ]
    done = run(*args, "-q")
    assert done.returncode == 1 and done.stdout == ""
    for w in words:
        assert w in done.stderr, done.stderr
    (lat, lon), dist = nearest_usable(ds, usable, end)
    m = re.search(r"the nearest point the ship may use is ([-\d.]+),([-\d.]+), ([\d.]+) km away", done.stderr)
    assert m, done.stderr
    assert float(m.group(1)) == pytest.approx(lat, abs=1e-4)
    assert float(m.group(2)) == pytest.approx(lon, abs=1e-4)
    assert float(m.group(3)) == pytest.approx(dist, abs=0.05)
    assert "--snap" in done.stderr
    # --snap: the same point, said on stderr, and the route ends there.
    far = run(*args, "--snap", "-q")  # farther than --snap-km (20 km by default): refused
    assert far.returncode == 1 and "farther than --snap-km 20: give a point in water" in far.stderr
    snapped = run(*args, "--snap", "--snap-km", "100", "-q")  # a snap is said even with --quiet
    assert snapped.returncode == 0, snapped.stderr
    m = re.search(r"moved ([\d.]+) km to ([-\d.]+),([-\d.]+) \(--snap, at most 100 km\)", snapped.stderr)
    assert m and words[0] in snapped.stderr
    assert float(m.group(1)) == pytest.approx(dist, abs=0.05)
    assert (float(m.group(2)), float(m.group(3))) == pytest.approx((lat, lon), abs=1e-4)
    last = snapped.stdout.splitlines()[0].split("->")[1].split(";")[0].split()
    assert last == [_fmt_lat(lat), _fmt_lon(lon)]


def _fmt_lat(v):
    d, m = divmod(round(abs(v) * 60, 2), 60)
    return f"{int(d):02d}-{m:05.2f}N"


def _fmt_lon(v):
    d, m = divmod(round(abs(v) * 60, 2), 60)
    return f"{int(d):03d}-{m:05.2f}E"


@pytest.mark.cli
def test_a_start_off_the_chart_polygons_is_named(charts, kara):
    ds, usable = kara
    # 87 N 100 E is the uncharted hole of tests/panarctic.py: unknown ice, never open water.
    done = run(
        "route", str(charts[0]), "--from", "87,100", "--to", "77.7,104.0", "--vessel", "Arc7", *GRID, "-q"
    )
    assert done.returncode == 1
    assert "start 87,100 is on an impassable pixel (off the chart" in done.stderr
    (lat, lon), dist = nearest_usable(ds, usable, (87, 100))
    assert f"is {lat:.4f},{lon:.4f}, {dist:.1f} km away" in done.stderr


@pytest.mark.cli
def test_route_across_the_antimeridian_on_the_default_grid(charts, tmp_path):
    import json

    out = tmp_path / "r.geojson"
    done = run(
        "route",
        str(charts[0]),
        "--from",
        "68,-170",
        "--to",
        "72,165",
        "--vessel",
        "Arc7",
        "--out",
        str(out),
        "-q",
    )
    assert done.returncode == 0, done.stderr
    feature = json.loads(out.read_text())
    geom = feature["geometry"]
    assert geom["type"] == "MultiLineString"  # split at +-180 (RFC 7946)
    lon = [p[0] for line in geom["coordinates"] for p in line]
    assert min(lon) <= -170 + 0.1 and max(lon) >= 165 - 0.1  # both sides of +-180
    gc = km((68, -170), (72, 165))
    length = feature["properties"]["length"]
    assert gc * 0.995 <= length <= 1.03 * gc
    assert TABLE_2[91] == 25  # medium first-year ice everywhere outside 50-140 E
    assert feature["properties"]["cost"] == pytest.approx(25 * length, rel=1e-6)


def test_route_grid_choices():
    from seaway.ice.routegrid import route_grid

    g, note = route_grid((68, -170), (72, 165))  # across +-180: one box, longitudes past 180
    assert g.x[0] < 180 < g.x[-1] and g.x[-1] - g.x[0] < 60 and "300 km" in note
    assert np.allclose(np.diff(g.y), -0.05)
    g, _ = route_grid((78, 20), (80, -150), chart_bounds=(-180, 60.0, 180, 88.6))
    assert g.y[0] > 89.9 and g.x[0] == pytest.approx(-180 + (g.x[1] - g.x[0]) / 2)
    assert g.x[-1] - g.x[0] + (g.x[1] - g.x[0]) == pytest.approx(360)  # wraps: over the pole
    g, _ = route_grid((59.5, -44), (60.5, -48), chart_bounds=(-50, 59, -42, 61.5))
    d = g.y[0] - g.y[1]
    assert d == pytest.approx(0.008, rel=1e-6)  # 1/1000 of a small chart's 8 deg extent
    # clipped to the chart (to within the pixel that rounding the edges may add)
    assert g.y[-1] > 59 - d and g.y[0] < 61.5 + d and g.x[0] > -50 - 2 * d and g.x[-1] < -42 + 2 * d
    with pytest.raises(ValueError, match="lie outside the chart"):
        route_grid((10, 10), (11, 11), chart_bounds=(-50, 59, -42, 61.5))
