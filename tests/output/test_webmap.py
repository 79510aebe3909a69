"""Interactive HTML maps (seaway.webmap): the page is parsed and checked, not only produced: the
route's coordinates, one popup per waypoint with its leg, the image layers and their colours, no
network URL for scripts or styles, atomic writes."""

import base64
import io
import json
import os
import re
import shutil
import stat
import subprocess
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

import seaway

folium = pytest.importorskip("folium")
from matplotlib import image  # noqa: E402

from seaway import plot  # noqa: E402
from seaway.output import webmap  # noqa: E402


@pytest.fixture
def ice_route():
    """75-80 N, 20-60 E: thick first-year ice (93) west of 40 E, multi-year ice (97) east of it,
    an island; the route goes around it, at 12 kn."""
    lat, lon = np.linspace(80, 75, 51), np.linspace(20, 60, 161)
    stage = np.where(lon[None, :] < 40, 93.0, 97.0) + np.zeros((51, 1))
    land = np.zeros(stage.shape, bool)
    land[20:30, 70:90] = True
    cost = xr.DataArray(np.where(stage == 93, 1.0, 3.0), dims=("lat", "lon"), coords={"lat": lat, "lon": lon})
    r = seaway.route(cost, (78, 22), (77, 58), land=land).smoothed()
    r = r.with_environment({"stage_of_development": stage})
    r = r.with_speed(12.0)
    return r


def _overlays(page):
    """[(PNG image, [[south, west], [north, east]])] of the page's image layers, in order."""
    out = []
    for m in re.finditer(
        r'L\.imageOverlay\(\s*"data:image/png;base64,([^"]+)",\s*(\[\[.*?\]\])', page, flags=re.S
    ):
        out.append(
            (image.imread(io.BytesIO(base64.b64decode(m.group(1))), format="png"), json.loads(m.group(2)))
        )
    return out


def test_the_page_holds_the_route_its_waypoints_and_the_ice(ice_route):
    r = ice_route
    page = webmap.html_text(r)
    # The polyline is the route, vertex by vertex.
    line = json.loads(re.search(r"L\.polyline\(\s*(\[\[.*?\]\])", page, flags=re.S).group(1))
    np.testing.assert_allclose(line, r.coords, rtol=0, atol=1e-9)
    # One marker and popup per waypoint; each popup gives its leg's course, distance and time.
    popups = [json.loads(p) for p in re.findall(r'\.bindPopup\(("(?:[^"\\]|\\.)*")', page)]
    legs = r.legs()
    assert len(popups) == len(r.waypoint_index) == len(legs) + 1
    for text, leg in zip(popups, legs):
        assert f"course {leg.course:05.1f}&deg;, {leg.distance_nm:.2f} nm" in text
        assert f"time {leg.time_h:.2f} h at 12 kn" in text
        assert "stage_of_development: up to" in text
    assert popups[0].startswith("<b>waypoint 1</b><br>78&deg;00.0'N 022&deg;00.0'E")
    assert "end:" in popups[-1]
    # Two image layers: the land around, and the chart in the WMO stage colours.
    (land, land_bounds), (chart, bounds) = _overlays(page)
    np.testing.assert_allclose(bounds, [[74.95, 19.875], [80.05, 60.125]], atol=1e-9)
    assert land_bounds[0][0] < 74.95 and land_bounds[1][1] > 60.125
    rgb = np.rint(chart[..., :3] * 255).astype(int)
    west, east = rgb[5, 10], rgb[5, -10]
    assert tuple(west) == (0, 120, 0) and tuple(east) == (200, 0, 0)  # thick FY, multi-year

    # The island (rows 20-29: 78.05-77.05 N) lands on the rows of Web Mercator that cover it:
    # image row i (centre at i + 0.5 of 51) is land iff its centre's y lies within the island's.
    def merc(lat):
        return np.degrees(np.arcsinh(np.tan(np.radians(lat))))

    top, bottom = ((merc(80.05) - merc(v)) / (merc(80.05) - merc(74.95)) * 51 for v in (78.05, 77.05))
    island = np.flatnonzero((np.abs(rgb - [200, 185, 150]).max(axis=-1) == 0).any(axis=1))  # tan
    np.testing.assert_array_equal(island, [i for i in range(51) if top < i + 0.5 < bottom])
    for name in ("land (global-land-mask)", "ice: WMO colour code by stage of development", '"route"'):
        assert name in page
    assert "multi-year ice" in page and "thick first-year ice" in page  # the legend


def test_no_script_or_style_comes_from_the_network(ice_route):
    page = webmap.html_text(ice_route)
    tags = re.findall(r"<(?:script|link|img)\b[^>]*>", page, flags=re.I)
    assert not [t for t in tags if re.search(r"(?:src|href)\s*=", t)]  # all inline
    assert "L.tileLayer" not in page  # no tile server
    assert "Leaflet 1.9" in page or "version" in page and "leaflet" in page.lower()
    assert "$(" not in page and "jQuery" not in page  # folium's popups need jQuery: not used
    assert re.search(r"url\(data:image/png;base64,", page)  # leaflet.css images inlined


def test_a_route_across_the_antimeridian_stays_continuous():
    lat, lon = np.linspace(70, 60, 41), np.linspace(170, 190, 81) % 360
    lon = np.where(lon > 180, lon - 360, lon)
    cost = xr.DataArray(np.ones((41, 81)), dims=("lat", "lon"), coords={"lat": lat, "lon": lon})
    r = seaway.route(cost, (65, 172), (65, -172))
    page = webmap.html_text(r)
    line = np.array(json.loads(re.search(r"L\.polyline\(\s*(\[\[.*?\]\])", page, flags=re.S).group(1)))
    assert line[0, 1] == pytest.approx(172) and line[-1, 1] == pytest.approx(188)
    assert np.all(np.abs(np.diff(line[:, 1])) < 180)  # no jump back across the antimeridian
    (_, _), (_, bounds) = _overlays(page)
    assert bounds[0][1] == pytest.approx(169.875) and bounds[1][1] == pytest.approx(190.125)


def test_explore_returns_a_folium_map_and_to_html_writes_atomically(ice_route, tmp_path):
    m = ice_route.explore()
    assert isinstance(m, folium.Map)
    path = tmp_path / "route.html"
    path.write_text("old")
    ice_route.to_html(path)
    assert path.read_text().startswith("<!DOCTYPE html>")
    planar = seaway.route(np.ones((5, 5)), (0, 0), (4, 4))
    with pytest.raises(ValueError, match="lat/lon chart"):
        planar.to_html(tmp_path / "planar.html")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["route.html"]  # nothing half-written
    old = os.umask(0o022)
    try:  # a new file's usual permissions, not the temporary file's 0600
        ice_route.to_html(tmp_path / "shared.html")
        plot.plot_route(ice_route, tmp_path / "shared.png", size=(4, 3), dpi=30)
    finally:
        os.umask(old)
    assert stat.S_IMODE((tmp_path / "shared.html").stat().st_mode) == 0o644
    assert stat.S_IMODE((tmp_path / "shared.png").stat().st_mode) == 0o644
    (tmp_path / "shared.html").unlink(), (tmp_path / "shared.png").unlink()
    seaway.export.write(ice_route, tmp_path / "r.htm")
    written = (tmp_path / "r.htm").read_text()
    assert written.count('.bindPopup("') == len(ice_route.waypoint_index)


def test_a_chart_in_any_row_and_column_order_gives_the_same_image(ice_route):
    """Rows south to north and columns east to west: the image still goes north-up and west to
    east, so the page shows the same colours in the same places."""
    c = ice_route.chart.template
    stage = ice_route.environment["stage_of_development"]
    flipped = c.isel(lat=slice(None, None, -1), lon=slice(None, None, -1))
    land = np.asarray(ice_route.chart.land, bool)[::-1, ::-1]
    r = seaway.route(flipped, (78, 22), (77, 58), land=land)
    r = r.with_environment({"stage_of_development": stage[::-1, ::-1]})
    (_, _), (flip_image, flip_bounds) = _overlays(webmap.html_text(r))
    (_, _), (image_, bounds) = _overlays(webmap.html_text(ice_route))
    np.testing.assert_allclose(flip_bounds, bounds, atol=1e-9)
    np.testing.assert_array_equal(flip_image, image_)


def test_a_cost_map_without_ice_shows_the_cost():
    lat, lon = np.linspace(70, 60, 21), np.linspace(10, 30, 41)
    u = np.tile(np.linspace(1, 5, 41), (21, 1))
    r = seaway.route(
        xr.DataArray(u, dims=("lat", "lon"), coords={"lat": lat, "lon": lon}), (65, 11), (65, 29)
    )
    page = webmap.html_text(r)
    assert "cost per unit length (1 dark to 5 light)" in page
    (_, _), (chart, _) = _overlays(page)
    assert chart[10, 0, :3].sum() < chart[10, -1, :3].sum()  # viridis: dark to light


@pytest.mark.cli
@pytest.mark.skipif(shutil.which("node") is None, reason="node is not installed")
def test_the_page_scripts_are_valid_javascript(ice_route, tmp_path):
    page = webmap.html_text(ice_route)
    scripts = re.findall(r"<script>(.*?)</script>", page, flags=re.S)
    assert len(scripts) >= 2  # folium's flags, Leaflet, the map
    for k, body in enumerate(scripts):
        f = tmp_path / f"s{k}.js"
        f.write_text(body)
        done = subprocess.run(["node", "--check", str(f)], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr


def _jsdom():
    if shutil.which("node") is None:
        return None
    for root in ("/usr/share/nodejs", "/usr/lib/node_modules", "/usr/local/lib/node_modules"):
        if (Path(root) / "jsdom").is_dir():
            return root
    return None


@pytest.mark.cli
@pytest.mark.skipif(_jsdom() is None, reason="node with jsdom is not installed")
def test_leaflet_builds_the_map_in_a_headless_dom(ice_route, tmp_path):
    """The page run in jsdom (which fetches nothing): Leaflet from the page itself, the two image
    layers, the route, a marker with a popup per waypoint, the three overlay switches."""
    path = tmp_path / "route.html"
    ice_route.to_html(path)
    done = subprocess.run(
        ["node", str(Path(__file__).parents[1] / "support" / "webmap_check.js"), str(path)],
        capture_output=True,
        text=True,
        env={"NODE_PATH": _jsdom()},
        timeout=120,
    )
    assert done.returncode == 0, done.stderr
    seen = json.loads(done.stdout)
    n = len(ice_route.waypoint_index)
    assert seen["errors"] == [] and seen["leaflet"] == "1.9.4"
    assert seen["layers"]["image"] == 2 and seen["layers"]["polyline"] == 1
    assert seen["layers"]["circle"] == n and seen["popups"] == n
    assert seen["controls"] == [
        "land (global-land-mask)",
        "ice: WMO colour code by stage of development",
        "route",
    ]
