"""Issue 10 part 1: a SIGRID-3 chart in any CRS onto any grid. Every sampled pixel must get a
polygon that covers its centre in EPSG:3413 (the reference: shapely point-in-polygon on the
true polygons), or be off the chart where none does: on a synthetic pan-Arctic chart (rings
across +-180, one around the pole, holes, multi-part, a bow-tie ring; tests/panarctic.py) and
on every real chart in ../shared/data."""

import numpy as np
import pytest

pytest.importorskip("antimeridian")
pytest.importorskip("pyogrio")

from seaway.ice.grids import latlon_grid, projected_grid  # noqa: E402
from seaway.ice.sigrid import read_sigrid3  # noqa: E402
from support import panarctic  # noqa: E402
from support.data import SHARED_DATA  # noqa: E402

DATA = SHARED_DATA
REAL = sorted((DATA / "ice_charts_sigrid3").glob("*/*.shp")) + sorted(
    (DATA / "ice_charts_sigrid3").glob("*/*.gpkg")
)
GRIDS = {
    "Kara Sea 0.05 deg": lambda: latlon_grid(66, 82, 50, 110, 0.05),
    "Arctic lat/lon 0.25 deg": lambda: latlon_grid(60, 90, -180, 180, 0.25),
    "Bering 150..210 E": lambda: latlon_grid(60, 80, 150, 210, 0.1),
    "EPSG:3413": lambda: projected_grid("EPSG:3413", -3500, 3500, -3500, 3500, 20),
    "EPSG:3995": lambda: projected_grid("EPSG:3995", -3500, 3500, -3500, 3500, 20),
    "EPSG:3576": lambda: projected_grid("EPSG:3576", -3500, 3500, -3500, 3500, 20),
}


@pytest.fixture(scope="module")
def chart(tmp_path_factory):
    path = tmp_path_factory.mktemp("panarctic") / "panarctic.shp"
    return path, panarctic.write(path)


@pytest.mark.parametrize("name", sorted(GRIDS))
def test_every_pixel_gets_the_polygon_covering_its_centre(chart, name):
    path, truth = chart
    grid = GRIDS[name]()
    ds = read_sigrid3(path, grid)
    share, n = panarctic.agreement(ds, grid, truth)
    assert n == 4000 and share >= 0.995, f"{name}: {share:.4f}"
    assert np.array_equal(ds.off_chart.values, ds.polygon.values < 0)
    assert np.isnan(ds.CT.values[ds.off_chart.values]).all()


def _pixel(ds, grid, lat, lon):
    import pyproj

    x, y = lon, lat
    if not grid.geographic:
        x, y = pyproj.Transformer.from_crs("EPSG:4326", grid.crs, always_xy=True).transform(lon, lat)
        x, y = x / 1000, y / 1000
    x = (x - grid.x[0]) % 360 + grid.x[0] if grid.geographic else x
    return ds.isel(
        {grid.dims()[0]: int(np.abs(grid.y - y).argmin()), grid.dims()[1]: int(np.abs(grid.x - x).argmin())}
    )


def test_pole_holes_antimeridian_and_bowtie_by_value(chart):
    path, truth = chart
    n = len(truth)  # features: cells ..., 3 land, the polynya (W), the bow-tie
    polar = projected_grid("EPSG:3413", -3500, 3500, -3500, 3500, 20)
    ds = read_sigrid3(path, polar)
    pole = _pixel(ds, polar, 90, 0)
    assert float(pole.SA) == 95 and float(pole.CT) == 10 and not bool(pole.off_chart)
    polynya = _pixel(ds, polar, 88, 10)  # a hole in the pole cell, filled by open water
    assert int(polynya.polygon) == n - 2 and float(polynya.CT) == 0
    assert bool(_pixel(ds, polar, 87, 100).off_chart)  # a hole nothing fills
    bering = latlon_grid(60, 80, 150, 210, 0.1)
    ds = read_sigrid3(path, bering)
    assert bool(_pixel(ds, bering, 75, 180).off_chart)  # the hole straddling +-180
    for lon in (175, 185):  # ice on both sides of the antimeridian, outside that hole
        px = _pixel(ds, bering, 77, lon)
        assert float(px.SA) == 91 and float(px.CT) == 10
    for lat, lon in ((71.15, 155), (71.85, 155)):  # both triangles of the bow-tie
        px = _pixel(ds, bering, lat, lon)
        assert int(px.polygon) == n - 1 and float(px.SA) == 81 and float(px.CT) == 4
    assert ds.attrs["repaired_polygons"] >= 2
    kara = latlon_grid(66, 82, 50, 110, 0.05)
    ds = read_sigrid3(path, kara)
    assert bool(_pixel(ds, kara, 73, 55).land) and bool(_pixel(ds, kara, 79, 100).land)
    assert float(_pixel(ds, kara, 74, 75).SA) == 87 and not ds.off_chart.values.any()


def _real_truth(path):
    """The file's polygons, repaired and densified in their own CRS, in EPSG:3413."""
    import pyogrio.raw
    import pyproj
    import shapely

    meta, _, wkb, _ = pyogrio.raw.read(path)
    geoms = shapely.make_valid(shapely.from_wkb(wkb))
    crs = pyproj.CRS.from_user_input(meta["crs"])
    geoms = shapely.segmentize(geoms, 0.05 if crs.is_geographic else 5000.0)
    tr = pyproj.Transformer.from_crs(crs, "EPSG:3413", always_xy=True)
    moved = shapely.transform(geoms, lambda xy: np.column_stack(tr.transform(xy[:, 0], xy[:, 1])))
    return moved, tr


@pytest.mark.needs_data("ice_charts_sigrid3")
@pytest.mark.parametrize("path", REAL, ids=[p.name for p in REAL])
def test_real_charts_on_latlon_and_polar_grids(path):
    import shapely

    truth, _ = _real_truth(path)
    x0, y0, x1, y1 = shapely.total_bounds(truth) / 1000
    step = max(x1 - x0, y1 - y0) / 300
    polar = projected_grid(
        "EPSG:3413", np.floor(x0), np.floor(x0) + 300 * step, np.floor(y0), np.floor(y0) + 300 * step, step
    )
    lon, lat = panarctic.TO_LONLAT.transform(
        *np.meshgrid(np.linspace(x0, x1, 50) * 1000, np.linspace(y0, y1, 50) * 1000)
    )
    s, w = np.floor(lat.min()), np.floor(lon.min())
    geo = latlon_grid(
        s,
        s + 0.02 * np.ceil((lat.max() - s) / 0.02),
        w,
        w + 0.04 * np.ceil((lon.max() - w) / 0.04),
        (0.02, 0.04),
    )
    for grid in (polar, geo):
        ds = read_sigrid3(path, grid)
        share, _ = panarctic.agreement(ds, grid, truth)
        assert share >= 0.995, f"{path.name} on {grid.crs}: {share:.4f}"
