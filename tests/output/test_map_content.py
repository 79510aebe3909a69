"""What the maps show, read from the files `seaway route --plot/--out .html` writes: a chart with
stages coloured by stage of development (WMO colour code), open water in the ice-free colour
with its legend entry, fast ice grey as fast ice (land tan, not grey), with --depth the shoals
below draft + UKC and the least-depth point, the HTML legend a Leaflet control (stacked with the
scale bar, never under it), start and end told apart. On a synthetic chart of the AARI fast-ice
shape, the real DMI chart of 1 May 2014 (fast ice in Disko Bay) and the real ETOPO5 depths."""

import base64
import io
import json
import re

import numpy as np
import pytest
import xarray as xr

from seaway.cli import main

pytest.importorskip("folium")
pytest.importorskip("pyogrio")
shapely = pytest.importorskip("shapely")
from matplotlib import image  # noqa: E402

from seaway.output import mapframe  # noqa: E402
from support.data import SHARED_DATA  # noqa: E402
from support.sigrid import write_fast_channel  # noqa: E402

pytestmark = pytest.mark.cli
DMI = ("ice_charts_sigrid3", "dmi_greenland", "201405011000_SouthWest_RIC.shp")
ETOPO = SHARED_DATA / "bathymetry" / "etopo5_arctic_60N.nc"
FAST, ICE_FREE, LAND, SHOAL = (150, 150, 150), (0, 100, 255), (200, 185, 150), (0, 229, 229)


@pytest.fixture
def legends(monkeypatch):
    """The legend labels of every PNG map drawn (read off the figure as it is saved)."""
    seen = []
    real = mapframe.MapFrame.png

    def spy(m, dpi):
        seen.append([t.get_text() for lg in m.fig.legends for t in lg.get_texts()])
        return real(m, dpi)

    monkeypatch.setattr(mapframe.MapFrame, "png", spy)
    return seen


def count(rgb_image, rgb, tol=2):
    return int((np.abs(rgb_image[..., :3].astype(int) - rgb).max(axis=-1) <= tol).sum())


def png_rgb(path):
    return np.rint(image.imread(path)[..., :3] * 255).astype(int)


def overlay(page, k=1):
    """The k-th image layer of the page (0: the land around, 1: the chart), as RGB."""
    found = re.findall(r'L\.imageOverlay\(\s*"data:image/png;base64,([^"]+)"', page)
    return np.rint(image.imread(io.BytesIO(base64.b64decode(found[k])), format="png")[..., :3] * 255).astype(
        int
    )


def legend_html(page):
    m = re.search(
        r'L\.control\(\{position: "(\w+)"\}\);\s*\w+\.onAdd = function \(\) \{ var div = '
        r'L\.DomUtil\.create\(.div.\); div\.innerHTML = ("(?:[^"\\]|\\.)*")',
        page,
    )
    assert m, "no legend control"
    return m.group(1), json.loads(m.group(2))


@pytest.fixture(scope="module")
def fast_sea(tmp_path_factory):
    """AARI's winter shape (support.sigrid.write_fast_channel)."""
    return str(write_fast_channel(tmp_path_factory.mktemp("fastmap") / "fast.shp"))


def test_fast_ice_open_water_and_land_on_both_maps(fast_sea, tmp_path, legends, capsys):
    png, page_path = tmp_path / "m.png", tmp_path / "m.html"
    code = main(
        [
            "route",
            fast_sea,
            "--from",
            "72.05,61.55",
            "--to",
            "72.05,78.55",
            "--grid",
            "70,75,60,80,0.1",
            "--escort",  # the fast ice is taken as thick first-year (1.6 m): Arc7 is escorted
            "--plot",
            str(png),
            "--out",
            str(page_path),
            "-q",
        ]
    )
    assert code == 0, capsys.readouterr().err
    (labels,) = legends
    assert {"fast ice", "ice free", "land", "start", "end"} <= set(labels)
    rgb = png_rgb(png)
    assert count(rgb, FAST) > 5000 and count(rgb, ICE_FREE) > 1000 and count(rgb, LAND) > 2000
    page = page_path.read_text()
    chart = overlay(page)
    assert count(chart, FAST) > 0.5 * chart.shape[0] * chart.shape[1] * 14 / 20 * 3 / 5
    assert count(chart, ICE_FREE) > 0 and count(chart, LAND) > 0
    corner, box = legend_html(page)
    assert corner == "bottomright" and "L.control.scale" in page  # the scale bar: bottom left
    for label in (
        "ice: WMO colour code by stage of development",
        "fast ice",
        "ice free",
        "land",
        "start",
        "end",
    ):
        assert label in box
    assert "position:fixed" not in page  # no box laid over the map's own controls
    assert "bindTooltip(\n" in page or ".bindTooltip(" in page
    assert re.search(
        r"L\.divIcon\(.*?background:#ff00ff;border:2px solid black", page, flags=re.S
    )  # the end: a square
    assert re.search(r'"start"', page) and re.search(r'"end"', page)  # their tooltips


@pytest.mark.needs_data(*DMI)
def test_real_dmi_fast_ice_is_grey_on_the_stage_map(shared_data, tmp_path, legends, capsys):
    png, page_path = tmp_path / "d.png", tmp_path / "d.html"
    code = main(
        [
            "route",
            str(shared_data.joinpath(*DMI)),
            "--from",
            "68.9,-53.0",
            "--to",
            "66.3,-54.5",
            "--grid",
            "65,71,-64,-50,0.1",
            "--plot",
            str(png),
            "--out",
            str(page_path),
            "-q",
        ]
    )
    assert code == 0, capsys.readouterr().err
    (labels,) = legends
    assert "fast ice" in labels and "thin first-year ice" in labels and "ice free" in labels
    assert count(png_rgb(png), FAST) > 20  # 48 pixels of 0.1 deg in Disko Bay
    page = page_path.read_text()
    assert count(overlay(page), FAST) >= 48
    assert "fast ice" in legend_html(page)[1]


@pytest.mark.slow
@pytest.mark.needs_data(ETOPO)
def test_shoals_and_the_least_depth_are_drawn(tmp_path, legends, capsys):
    """Open water around the Ob Bay with ETOPO5's depths and a draft of 8 m: water shallower than
    8.8 m is cyan on both maps, with its legend entry, and the least depth of the route marked."""
    lat, lon = np.round(np.arange(68.025, 76, 0.05), 3), np.round(np.arange(64.08, 80, 0.16), 2)
    chart = tmp_path / "open.nc"
    xr.Dataset(
        {"cost": (("lat", "lon"), np.ones((lat.size, lon.size)))}, coords={"lat": lat, "lon": lon}
    ).to_netcdf(chart)
    png, page_path, out = tmp_path / "o.png", tmp_path / "o.html", tmp_path / "o.geojson"
    code = main(
        [
            "route",
            str(chart),
            "--from",
            "74.5,72",
            "--to",
            "69,73.5",
            "--depth",
            str(ETOPO),
            "--draft",
            "8",
            "--plot",
            str(png),
            "--out",
            str(page_path),
            "--out",
            str(out),
            "-q",
        ]
    )
    assert code == 0, capsys.readouterr().err
    least = json.loads(out.read_text())["properties"]["least_depth_m"]
    (labels,) = legends
    assert "shoal: shallower than 8.8 m (draft + UKC)" in labels and f"least depth {least:.1f} m" in labels
    assert count(png_rgb(png), SHOAL) > 500
    page = page_path.read_text()
    box = legend_html(page)[1]
    assert "shoal: shallower than 8.8 m (draft + UKC)" in box and f"least depth {least:.1f} m" in box
    assert count(overlay(page), SHOAL) > 100
