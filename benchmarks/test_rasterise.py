"""Rasterising a pan-Arctic SIGRID-3 chart (lon/lat, rings across +-180 and around the pole; a
few hundred polygons, tests/panarctic.py) onto a 0.05 deg Kara Sea grid (270 x 1100 pixels), as
read_sigrid3 does it, against a peer: shapely point-in-polygon of every pixel centre in
EPSG:3413 (STRtree), in the same run. Target: <= 2 s. Asserts the two agree."""

import numpy as np
import pytest

from seaway.ice.grids import latlon_grid
from seaway.ice.sigrid import read_sigrid3
from support import panarctic

from .conftest import record

GRID = (66.5, 80.0, 58.5, 113.5, 0.05)  # Kara Gate to the Vilkitsky Strait


@pytest.fixture(scope="module")
def chart(tmp_path_factory):
    path = tmp_path_factory.mktemp("panarctic") / "panarctic.shp"
    truth = panarctic.write(path, cell_km=250.0)
    return path, truth


def _peer(truth, grid):
    import shapely

    lon, lat = np.meshgrid(grid.x, grid.y)
    pts = shapely.points(*panarctic.TO_POLAR.transform(lon, lat)).ravel()
    pairs = shapely.STRtree(truth).query(pts, predicate="intersects")
    index = np.full(pts.size, -1)
    index[pairs[0]] = pairs[1]
    return index.reshape(grid.shape)


def test_read_sigrid3_kara_grid(benchmark, chart):
    path, truth = chart
    grid = latlon_grid(*GRID)
    ds = benchmark.pedantic(read_sigrid3, (path, grid), rounds=5, iterations=1, warmup_rounds=1)
    agree = float((ds.polygon.values == _peer(truth, grid)).mean())
    record(
        "read_sigrid3 pan-Arctic -> Kara 0.05 deg",
        benchmark,
        f"{len(truth)} polygons, {grid.shape[0]} x {grid.shape[1]} px, agreement {agree:.4%}",
    )
    assert grid.shape == (270, 1100) and len(truth) >= 300 and agree >= 0.995
    assert benchmark.stats is None or benchmark.stats.stats.median <= 2.0


def test_peer_point_in_polygon(benchmark, chart):
    path, truth = chart
    grid = latlon_grid(*GRID)
    benchmark.pedantic(_peer, (truth, grid), rounds=2, iterations=1)
    record("peer: shapely STRtree point-in-polygon", benchmark, "pixel centres in EPSG:3413")
