"""PNG maps (seaway.plot), checked as images: size and route-coloured pixels."""

import numpy as np
import pytest
import xarray as xr

import seaway

pytest.importorskip("matplotlib")
from seaway import plot  # noqa: E402
from matplotlib import image  # noqa: E402


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
    grey = (np.abs(im[..., :3] - 140 / 255).max(axis=-1) < 0.02).sum()
    assert grey > 2000  # the land block


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
        plot._pyplot()
