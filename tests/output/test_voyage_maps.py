"""The maps of a weather voyage (`seaway route [CHART] --forecast FILE --plot map.png`) show what
the ship meets (issue 27 item 4): the sea coloured by the forecast's main field at the departure
(wave height, else wind speed), its colour bar naming the quantity, unit and time and holding
the forecast's own values then; the ice in the WMO colours; and on the real DMI chart of Cape
Farewell the pixels no polygon covers hatched as off chart, never painted as land. Read off
the matplotlib figure as it is saved."""

import base64
import io
import re

import numpy as np
import pytest
import xarray as xr

from seaway.cli import main
from support import forecast_files as ff

pytest.importorskip("cartopy")
from matplotlib import image  # noqa: E402
from matplotlib.collections import QuadMesh  # noqa: E402

from seaway.output import mapframe  # noqa: E402
from seaway.output.voyagemap import OFF_CHART_COLOUR, OFF_CHART_LABEL  # noqa: E402

pytestmark = pytest.mark.cli
DMI = ("ice_charts_sigrid3", "dmi_greenland", "201304100920_CapeFarewell_RIC.shp")


@pytest.fixture
def drawn(monkeypatch):
    """Every PNG map drawn: {"land": the mask given to the land layer, "bar": (colour bar label,
    its mesh's drawn values), "legend": labels, "hatched": off-chart hatching drawn}."""
    maps = []
    real_init, real_png = mapframe.MapFrame.__init__, mapframe.MapFrame.png
    real_land, real_hatch = mapframe.MapFrame.chart_land, mapframe.MapFrame.hatch

    def init(m, *args, **kw):
        maps.append({"land": None, "hatched": None})
        return real_init(m, *args, **kw)

    def land(m, mask=None):
        maps[-1]["land"] = m.chart.land if mask is None else mask
        return real_land(m, mask)

    def hatch(m, mask, **kw):
        maps[-1]["hatched"] = np.asarray(mask, bool).copy()
        return real_hatch(m, mask, **kw)

    def png(m, dpi):
        bars = [c for c in m.ax.collections if isinstance(c, QuadMesh) and c.colorbar is not None]
        one = maps[-1]
        one["bar"] = [(c.colorbar.ax.get_ylabel(), np.ma.asarray(c.get_array())) for c in bars]
        one["legend"] = [t.get_text() for lg in m.fig.legends for t in lg.get_texts()]
        one["lat"], one["lon"] = np.asarray(m.chart.lat, float), np.asarray(m.chart.lon, float)
        one["chart_land"] = None if m.chart.land is None else np.asarray(m.chart.land, bool)
        return real_png(m, dpi)

    monkeypatch.setattr(mapframe.MapFrame, "__init__", init)
    monkeypatch.setattr(mapframe.MapFrame, "png", png)
    monkeypatch.setattr(mapframe.MapFrame, "chart_land", land)
    monkeypatch.setattr(mapframe.MapFrame, "hatch", hatch)
    return maps


def _route(capsys, *argv):
    code = main(["route", *map(str, argv), "-q"])
    out, err = capsys.readouterr()
    assert code == 0, err
    return out


@pytest.mark.parametrize(
    "depart, weights", [("2026-10-01T06:00", {1: 1.0}), ("2026-10-01T09:00", {1: 0.5, 2: 0.5})]
)
def test_a_wave_voyage_is_drawn_on_its_wave_height_at_departure(tmp_path, capsys, drawn, depart, weights):
    """The gale's waves (support.forecast_files): the colour bar says significant wave height in
    metres at the departure, and the sea's drawn values are the forecast's at that time on every
    sea pixel (linear between frames, as the engine reads it)."""
    waves = tmp_path / "waves.nc"
    ff.in_memory(("hs", "wdir", "per")).to_netcdf(waves)
    png = tmp_path / "w.png"
    _route(capsys, "--forecast", waves, "--from=70.5,21", "--to=73.5,29", "--depart", depart, "--plot", png)
    assert png.stat().st_size > 10_000
    (one,) = drawn
    ((label, values),) = one["bar"]
    assert label == f"significant wave height (m) at departure, {depart.replace('T', ' ')} UTC"
    hs = sum(w * ff.gale()["hs"][k].astype(float) for k, w in weights.items())
    sea = ~one["chart_land"]
    assert sea.sum() > 300 and not values.mask[sea].any() and values.mask[~sea].all()
    np.testing.assert_allclose(values[sea], hs[sea], rtol=1e-6)
    assert values.min() == pytest.approx(hs[sea].min()) and values.max() == pytest.approx(hs[sea].max())
    assert "land" in one["legend"] and one["hatched"] is None  # no ice chart: nothing off chart


def test_a_wind_forecast_is_drawn_as_wind_speed(tmp_path, capsys, drawn):
    winds = tmp_path / "winds.nc"
    ff.in_memory(("wind_e", "wind_n")).to_netcdf(winds)
    _route(capsys, "--forecast", winds, "--from=70.5,21", "--to=73.5,29", "--plot", tmp_path / "v.png")
    ((label, values),) = drawn[0]["bar"]
    g = ff.gale()
    speed = np.hypot(g["wind_e"][0].astype(float), g["wind_n"][0].astype(float))
    assert label == "wind speed (m/s) at departure, 2026-10-01 00:00 UTC"
    sea = ~drawn[0]["chart_land"]
    np.testing.assert_allclose(values[sea], speed[sea], rtol=1e-6)


def _cape_farewell_waves(path):
    """Waves over Cape Farewell on 10 April 2013, higher to the south: 1 to 4 m."""
    lat, lon = np.arange(57.0, 63.01, 0.1), np.arange(-52.0, -38.99, 0.1)
    t = np.datetime64("2013-04-10T12", "ns") + np.arange(3) * np.timedelta64(6, "h")
    hs = (1.0 + 3.0 * (63 - lat) / 6)[None, :, None] * np.ones((3, 1, lon.size))
    xr.Dataset(
        {
            "hs": (("time", "lat", "lon"), hs, {"standard_name": "sea_surface_wave_significant_height"}),
            "wdir": (
                ("time", "lat", "lon"),
                np.full(hs.shape, 270.0),
                {"standard_name": "sea_surface_wave_from_direction"},
            ),
        },
        coords={"time": t, "lat": lat, "lon": lon},
    ).to_netcdf(path)


@pytest.mark.needs_data(*DMI)
def test_ice_and_waves_on_the_dmi_chart_draw_off_chart_as_off_chart(shared_data, tmp_path, capsys, drawn):
    """The DMI chart of 10 April 2013 leaves the open Atlantic south-east of Cape Farewell
    uncovered (no polygon): those pixels are hatched as off chart and are not in the land the
    map paints; the ice is in the WMO stage colours, and the open sea shows the wave height."""
    waves = tmp_path / "waves.nc"
    _cape_farewell_waves(waves)
    png, page = tmp_path / "iw.png", tmp_path / "iw.html"
    _route(
        capsys,
        shared_data.joinpath(*DMI),
        "--forecast",
        waves,
        "--vessel",
        "Arc7",
        "--from=59.5,-44",
        "--to=60.5,-48",
        "--grid",
        "58,62,-50,-40,0.1",
        "--plot",
        png,
        "--out",
        page,
    )
    (one,) = drawn
    off, land, routed_land = one["hatched"], one["land"], one["chart_land"]
    assert off is not None and off.sum() >= 20  # the wedge south-east of 59 N 41 W
    lat, lon = one["lat"], one["lon"]
    south = lat[:, None] < 59.5
    assert (off & south & (lon > -42.0)).sum() >= 20  # the wedge in the open Atlantic ...
    assert not (off & south & (lon < -42.0)).any()  # ... and none in the covered sea west of it
    assert routed_land[off].all()  # closed to the voyage ...
    assert not land[off].any()  # ... but not painted as land
    assert (land == (routed_land & ~off)).all()  # Greenland still is
    assert OFF_CHART_LABEL in one["legend"] and "land" in one["legend"]
    assert any(t.startswith("ice: ") and "ice" in t[5:] for t in one["legend"])
    ((label, values),) = one["bar"]
    assert label == "significant wave height (m) at departure, 2013-04-10 12:00 UTC"
    assert values.mask[off].all() and values.mask[land].all()
    assert 1.0 <= values.min() and values.max() <= 4.0 and values.count() > 1000
    # the HTML map: the same layers in its chart image and legend
    text = page.read_text()
    chart = re.findall(r'L\.imageOverlay\(\s*"data:image/png;base64,([^"]+)"', text)[1]
    rgb = np.rint(image.imread(io.BytesIO(base64.b64decode(chart)), format="png")[..., :3] * 255).astype(int)
    grey = [int(OFF_CHART_COLOUR[i : i + 2], 16) for i in (1, 3, 5)]
    assert (np.abs(rgb - grey).max(axis=-1) <= 2).sum() >= 20
    assert OFF_CHART_LABEL in text and "significant wave height (m) at departure" in text
