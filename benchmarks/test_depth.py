"""Resampling ETOPO5 (../shared/data/bathymetry) onto chart grids with seaway.depth.depth_on_grid,
against the peer xarray's coarsen().max() where the ratio of resolutions is a whole number
(0.25 deg pixels = 3 x 3 nodes; the answers must be equal), and onto the 0.05 deg Kara Sea
grid (270 x 1100, interpolation) and a 20 km EPSG:3413 grid of the whole Arctic (binned)."""

import numpy as np
import pytest
import xarray as xr

from seaway.depth import depth_on_grid, open_bathymetry
from seaway.ice.grids import latlon_grid, projected_grid
from support.data import SHARED_DATA

from .conftest import record


def _etopo():
    path = SHARED_DATA / "bathymetry" / "etopo5_arctic_60N.nc"
    if not path.exists():
        pytest.skip(f"{path} is absent")
    return path


S, W = 66 - 1 / 24, 50 - 1 / 24  # pixel edges half a node off the nodes: 3 whole nodes each


@pytest.fixture(scope="module")
def etopo():
    b = open_bathymetry(_etopo())
    b.raw.load()
    return b


def _peer(b):
    box = b.raw.sel(lat=slice(S, S + 16), lon=slice(W, W + 60))
    return -box.coarsen(lat=3, lon=3).max()


def test_depth_binned_minimum_vs_coarsen(benchmark, etopo):
    grid = latlon_grid(S, S + 16, W, W + 60, 0.25)
    z = benchmark.pedantic(
        depth_on_grid, (etopo,), {"lat": grid.y, "lon": grid.x}, rounds=5, iterations=1, warmup_rounds=1
    )
    peer = _peer(etopo)
    assert z.shape == (64, 240) == peer.shape
    assert np.array_equal(z.values[::-1], peer.values)  # rows north to south
    record("depth_on_grid ETOPO5 -> 0.25 deg (binned min)", benchmark, "equal to coarsen(3, 3)")


def test_peer_coarsen(benchmark, etopo):
    benchmark.pedantic(_peer, (etopo,), rounds=5, iterations=1, warmup_rounds=1)
    record("peer: xarray coarsen(lat=3, lon=3).max()", benchmark, "whole-number ratio only")


def test_depth_kara_grid(benchmark, etopo):
    kara = latlon_grid(66.5, 80.0, 58.5, 113.5, 0.05)
    z = benchmark.pedantic(
        depth_on_grid, (etopo,), {"lat": kara.y, "lon": kara.x}, rounds=5, iterations=1, warmup_rounds=1
    )
    assert z.shape == (270, 1100) and np.isfinite(z.values).all()
    record("depth_on_grid ETOPO5 -> Kara 0.05 deg", benchmark, "270 x 1100, interpolation")


def test_depth_polar_grid(benchmark, etopo):
    g = projected_grid("EPSG:3413", -3500, 3500, -3500, 3500, 20)
    like = xr.DataArray(np.ones(g.shape), dims=g.dims(), coords=g.coords(), attrs={"crs": g.crs})
    z = benchmark.pedantic(depth_on_grid, (etopo, like), rounds=3, iterations=1)
    assert z.shape == (350, 350)
    record("depth_on_grid ETOPO5 -> EPSG:3413 20 km", benchmark, "350 x 350, 1.56 M nodes binned")
