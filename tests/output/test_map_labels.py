"""What a PNG map says (issue 27, item 4): its title names the chart file, not its full path;
a polar map labels each parallel on the parallel itself (where a parallel cuts the frame of a
polar map is far from where it crosses the chart: a start at 70.3 N was drawn beside "66°N")."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

import seaway

pytest.importorskip("matplotlib")
pytest.importorskip("cartopy")
from seaway import plot  # noqa: E402
from seaway.cli import main  # noqa: E402
from seaway.output import mapframe  # noqa: E402


@pytest.fixture
def figures(monkeypatch):
    """The figures of the maps drawn, and their titles."""
    figs, titles = [], []
    real_png, real_title = mapframe.MapFrame.png, mapframe.MapFrame.title
    monkeypatch.setattr(mapframe.MapFrame, "png", lambda m, dpi: (figs.append(m.fig), real_png(m, dpi))[1])
    monkeypatch.setattr(
        mapframe.MapFrame, "title", lambda m, text: (titles.append(text), real_title(m, text))[1]
    )
    return figs, titles


def _kara_like():
    """A Kara Sea-sized chart, 82-68 N, 50-110 E."""
    lat, lon = np.linspace(82.0, 68.0, 57), np.linspace(50.0, 110.0, 121)
    return xr.DataArray(np.ones((57, 121)), dims=("lat", "lon"), coords={"lat": lat, "lon": lon})


def _radius(ax, lon, lat):
    """Distance from the pole on the map (polar stereographic: it falls as the latitude rises)."""
    import cartopy.crs as ccrs

    x, y = ax.projection.transform_point(lon, lat, ccrs.PlateCarree())
    return float(np.hypot(x, y))


def test_parallels_are_labelled_on_their_parallels(figures, tmp_path):
    import cartopy.crs as ccrs

    r = seaway.route(_kara_like(), (70.3, 58.5), (77.7, 104.0))
    plot.plot_route(r, tmp_path / "k.png", size=(10, 7), dpi=60)
    (fig,), _ = figures
    ax = fig.axes[0]
    from cartopy.mpl.gridliner import Gridliner

    (grid,) = [a for a in ax.get_children() if isinstance(a, Gridliner)]
    assert not (grid.left_labels or grid.right_labels)  # no latitudes where parallels cut the frame
    labels = [t for t in ax.texts if t.get_gid() == "parallel label"]
    values = [float(t.get_text().rstrip("°N")) for t in labels]
    assert len(labels) >= 3 and values == sorted(values) and all(t.get_text().endswith("°N") for t in labels)
    frame = ax.get_window_extent()
    for t, value in zip(labels, values):
        shown = t.get_transform().transform(t.get_position())  # where the label is drawn
        assert frame.contains(*shown)
        x, y = ax.transData.inverted().transform(shown)
        lon, lat = ccrs.PlateCarree().transform_point(x, y, ax.projection)
        assert lat == pytest.approx(value, abs=1e-6)  # on its own parallel
    # the start (70.3 N) is drawn between the parallels labelled 70 and 72.5 N (or whichever bracket it)
    below = max(v for v in values if v <= 70.3)
    above = min(v for v in values if v > 70.3)
    start = _radius(ax, 58.5, 70.3)
    assert _radius(ax, 58.5, below) > start > _radius(ax, 58.5, above)
    assert below == 70.0 and above <= 72.5


def test_the_map_title_names_the_chart_file_not_its_path(figures, tmp_path):
    deep = tmp_path / "archive" / "ice" / "2026" / "03"
    deep.mkdir(parents=True)
    path = deep / "kara_chart.nc"
    lat, lon = np.linspace(76.0, 70.0, 31), np.linspace(60.0, 76.0, 41)
    stage = np.full((31, 41), 55.0)
    stage[20:, :] = 93.0
    xr.Dataset(
        {
            "stage_of_development": (("lat", "lon"), stage),
            "land": (("lat", "lon"), np.zeros((31, 41), np.int8)),
        },
        coords={"lat": lat, "lon": lon},
    ).to_netcdf(path)
    png = tmp_path / "r.png"
    args = [
        "route",
        str(path),
        "--from",
        "73,61",
        "--to",
        "73,75",
        "--vessel",
        "Arc7",
        "--plot",
        str(png),
        "-q",
    ]
    assert main(args) == 0
    (title,) = figures[1]
    assert "kara_chart.nc" in title and str(deep) not in title and "archive" not in title
    assert png.stat().st_size > 10_000
