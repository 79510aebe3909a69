"""PNG maps (seaway.plot), checked as images: size and route-coloured pixels."""

import numpy as np
import pytest
import xarray as xr

import seaway

pytest.importorskip("matplotlib")
from matplotlib import image  # noqa: E402

from seaway import plot  # noqa: E402
from seaway.output import mapframe  # noqa: E402
from seaway.output.style import fit_title  # noqa: E402


def _magenta(png):
    im = image.imread(png)
    return im.shape, int((np.abs(im[..., :3] - [1.0, 0.0, 1.0]).sum(axis=-1) < 0.1).sum())


@pytest.fixture
def chart():
    lat, lon = np.linspace(70, 60, 101), np.linspace(170, 190, 201)
    cost = np.random.default_rng(0).uniform(1, 3, (101, 201))
    land = np.zeros(cost.shape, bool)
    land[30:60, 80:120] = True
    return xr.DataArray(cost, dims=("lat", "lon"), coords={"lat": lat, "lon": lon}), land


def test_route_map(chart, tmp_path):
    da, land = chart
    r = seaway.route(da, (69, 171), (61, 189), land=land).smoothed()
    plot.plot_route(r, tmp_path / "r.png", size=(8, 6), dpi=100)
    shape, magenta = _magenta(tmp_path / "r.png")
    assert shape[:2] == (600, 800) and magenta > 500
    im = image.imread(tmp_path / "r.png")
    tan = (np.abs(im[..., :3] - np.array([200, 185, 150]) / 255).max(axis=-1) < 0.02).sum()
    assert tan > 2000  # the land block, light tan (grey is fast ice in the WMO colour code)


def test_cost_field_picture(chart, tmp_path):
    da, land = chart
    field = seaway.cost_field(da, (69, 171), land=land)
    plot.plot_cost_field(field, tmp_path / "f.png", size=(6, 4), dpi=50)
    shape, magenta = _magenta(tmp_path / "f.png")
    assert shape[:2] == (200, 300) and magenta == 0
    r = seaway.route(da, (69, 171), (61, 189), land=land)
    plot.plot_cost_field(field, tmp_path / "g.png", route=r, size=(6, 4), dpi=50)
    assert _magenta(tmp_path / "g.png")[1] > 50


def test_missing_matplotlib_names_the_extra(monkeypatch):
    import builtins

    real = builtins.__import__

    def fake(name, *args, **kwargs):
        if name == "matplotlib" or name.startswith("matplotlib."):
            raise ImportError("no matplotlib")
        return real(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", fake)
    with pytest.raises(ImportError, match=r'pip install "seaway\[plot\]"'):
        mapframe.pyplot()


def _count_rgb(png, rgb, tol=0.02):
    im = image.imread(png)[..., :3]
    return int((np.abs(im - np.array(rgb) / 255).max(axis=-1) < tol).sum())


def test_wmo_colour_classes():
    from seaway.ice.colours import classes, guess_code, tenths

    conc = np.array([[0.0, 0.5, 1.0, 3.9], [4.0, 7.0, 8.9, 10.0], [np.nan, 9.0, 6.9, 0.0]])
    index, table = classes(conc, "concentration")
    np.testing.assert_array_equal(index, [[0, 1, 2, 2], [3, 4, 4, 5], [-1, 5, 3, 0]])
    assert [rgb for _, rgb in table] == [
        (0, 100, 255),
        (150, 200, 255),
        (140, 255, 160),
        (255, 255, 0),
        (255, 125, 7),
        (255, 0, 0),
    ]
    np.testing.assert_allclose(tenths([0, 50, 100]), [0, 5, 10])  # percent
    np.testing.assert_allclose(tenths([0, 0.5, 1.0]), [0, 5, 10])  # fraction
    stage = np.array([[55, 81, 93], [97, 99, np.nan]])
    index, table = classes(stage, "stage")
    names = [table[k][0] if k >= 0 else None for k in index.ravel()]
    assert names == ["ice free", "new ice", "thick first-year ice", "multi-year ice", "undefined ice", None]
    assert table[index[0, 2]][1] == (0, 120, 0) and table[index[1, 0]][1] == (200, 0, 0)
    assert guess_code(stage) == "stage" and guess_code(conc) == "concentration"
    with pytest.raises(ValueError, match="'concentration' or 'stage'"):
        classes(stage, "thickness")


@pytest.fixture
def ice_chart():
    """75-80 N, 20-60 E: thick first-year ice (93) in the west, multi-year ice (97) in the east,
    an island; concentration 9/10 and 5/10."""
    lat, lon = np.linspace(80, 75, 51), np.linspace(20, 60, 161)
    stage = np.where(lon[None, :] < 40, 93.0, 97.0) + np.zeros((51, 1))
    conc = np.where(lon[None, :] < 40, 9.0, 5.0) + np.zeros((51, 1))
    land = np.zeros(stage.shape, bool)
    land[20:30, 70:90] = True
    cost = xr.DataArray(np.where(stage == 93, 1.0, 3.0), dims=("lat", "lon"), coords={"lat": lat, "lon": lon})
    return cost, land, stage, conc


def test_polar_map_in_wmo_colours_offline(ice_chart, tmp_path, monkeypatch):
    import socket

    def no_network(*args, **kwargs):
        raise AssertionError("the map tried to use the network")

    monkeypatch.setattr(socket.socket, "connect", no_network)  # no Natural Earth download
    cost, land, stage, conc = ice_chart
    r = seaway.route(cost, (78, 22), (77, 58), land=land).smoothed()
    plot.plot_route(r, tmp_path / "s.png", ice=stage, size=(10, 7.5), dpi=80)
    assert _count_rgb(tmp_path / "s.png", (0, 120, 0)) > 3000  # thick first-year ice
    assert _count_rgb(tmp_path / "s.png", (200, 0, 0)) > 3000  # multi-year ice
    assert _count_rgb(tmp_path / "s.png", (255, 0, 0)) < 50  # no concentration colours
    assert _magenta(tmp_path / "s.png")[1] > 300  # the route
    env = r.with_environment({"sea_ice_concentration": conc})
    plot.plot_route(env, tmp_path / "c.png", size=(10, 7.5), dpi=80)  # from the environment
    assert _count_rgb(tmp_path / "c.png", (255, 0, 0)) > 3000  # 9-10/10
    assert _count_rgb(tmp_path / "c.png", (255, 255, 0)) > 3000  # 4-6/10
    assert _count_rgb(tmp_path / "c.png", (0, 120, 0)) < 50


def test_map_projection_follows_the_hemisphere(ice_chart):
    import cartopy.crs as ccrs

    cost, land, _, _ = ice_chart
    north = seaway.chart.raster.as_chart(cost)
    south = seaway.chart.raster.as_chart(cost.assign_coords(lat=-cost.lat))
    try:
        m = mapframe.MapFrame(north, (6, 5))
        assert isinstance(m.ax.projection, ccrs.NorthPolarStereo)
        s = mapframe.MapFrame(south, (6, 5))
        assert isinstance(s.ax.projection, ccrs.SouthPolarStereo)
    finally:
        m.plt.close("all")


def test_a_long_title_is_wrapped_not_cut(ice_chart, tmp_path):
    cost, land, stage, _ = ice_chart
    r = seaway.route(cost, (78, 22), (77, 58), land=land)
    title = "route: NetCDF chart " + "/very/long/path" * 20 + "/chart.nc, ice impact for Arc7"
    plot.plot_route(r, tmp_path / "t.png", ice=stage, title=title, size=(8, 6), dpi=80)
    im = image.imread(tmp_path / "t.png")[..., :3]
    edges = np.concatenate([im[:, :2], im[:, -2:]], axis=1)
    assert (edges > 0.95).all()  # nothing drawn at the left or right edge: no text cut off


def test_a_long_chart_path_is_shortened_to_its_last_parts():
    path = "/data/ice/" + "archive/" * 12 + "2026/03/kara_sea_20260301.nc"
    text = fit_title(f"seaway route: NetCDF chart {path} (CT, SA), Arc7", 60)
    lines = text.split("\n")
    assert all(len(line) <= 60 for line in lines) and len(lines) <= 3
    assert ".../" in text and "kara_sea_20260301.nc" in text and text.endswith("Arc7")
    assert fit_title("short title", 60) == "short title"


def test_default_size_follows_the_map_aspect(ice_chart, tmp_path):
    cost, land, stage, _ = ice_chart
    r = seaway.route(cost, (78, 22), (77, 58), land=land)
    plot.plot_route(r, tmp_path / "a.png", ice=stage, dpi=50)
    h, w = image.imread(tmp_path / "a.png").shape[:2]
    assert w == 550 and 200 <= h < 550  # 11 inches wide; this chart is wider than high


def test_a_cost_field_keeps_its_colour_bar(chart, tmp_path, monkeypatch):
    """The field's map has a colour bar spanning the field's finite range."""
    da, land = chart
    field = seaway.cost_field(da, (69, 171), land=land)
    figures = []
    real_png = mapframe.MapFrame.png
    monkeypatch.setattr(mapframe.MapFrame, "png", lambda m, dpi: (figures.append(m.fig), real_png(m, dpi))[1])
    plot.plot_cost_field(field, tmp_path / "f.png", size=(6, 4), dpi=40)
    (fig,) = figures
    label = f"least accumulated cost from the start ({field.attrs['units']})"
    bars = [ax for ax in fig.axes if ax.get_ylabel() == label]
    assert len(bars) == 1
    v = field.values[np.isfinite(field.values)]
    assert bars[0].get_ylim() == pytest.approx((v.min(), v.max()), rel=1e-6)


def test_an_arrival_field_is_labelled_in_hours(tmp_path, monkeypatch):
    """An arrival field (hours to reach through a season) says so on its colour bar, not 'cost'."""
    from support.seasons import retreating_edge

    retreating_edge(days=3).to_netcdf(tmp_path / "s.nc")
    field = seaway.open_season(str(tmp_path / "s.nc")).arrival_field((71.0, 70.0), vessel="Arc7")
    figures = []
    real_png = mapframe.MapFrame.png
    monkeypatch.setattr(mapframe.MapFrame, "png", lambda m, dpi: (figures.append(m.fig), real_png(m, dpi))[1])
    plot.plot_cost_field(field, tmp_path / "f.png", size=(6, 4), dpi=40)
    plot.plot_cost_field(field, tmp_path / "g.png", size=(6, 4), dpi=40, label="hours from Sabetta")
    labels = [[ax.get_ylabel() for ax in fig.axes if ax.get_ylabel()] for fig in figures]
    assert labels == [["hours to reach after departure (waiting allowed) (h)"], ["hours from Sabetta"]]
