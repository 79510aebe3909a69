"""Great-circle corridors (papers 001, 003): paper 001's San Francisco -> Tokyo great circle."""

import numpy as np
import pytest
import xarray as xr

from seaway import NoRouteError
from seaway.base import sphere as geo
from seaway.corridor import corridor

SF = (37 + 40.4 / 60, -(122 + 25.9 / 60))
TOKYO = (35 + 35.4 / 60, 140 + 25.5 / 60)


@pytest.fixture(scope="module")
def pacific():
    return corridor(SF, TOKYO, hours=12, speed_kn=10, row_nm=20, m=10)


def test_paper_001_great_circle(pacific):
    """Paper 001: 37 legs of 120 nm, about 4440 nm, across the antimeridian."""
    c = pacific
    assert c.shape == (21, 38)
    assert c.distance_km / 1.852 == pytest.approx(4443.0, abs=0.5)
    assert c.leg_km / 1.852 == pytest.approx(120.08, abs=0.01)
    pyproj = pytest.importorskip("pyproj")
    sphere = pyproj.Geod(a=6371008.8, b=6371008.8)
    az, _, metres = sphere.inv(SF[1], SF[0], TOKYO[1], TOKYO[0])
    assert c.distance_km == pytest.approx(metres / 1000, rel=1e-9)
    assert geo.course_deg(*SF, *TOKYO) == pytest.approx(az % 360, abs=1e-6)
    track = c.track
    assert np.any(track[:, 1] > 170) and np.any(track[:, 1] < -170)  # both sides of 180
    # each layer's nodes are row_nm apart across the track and the track nodes equally spaced
    across = geo.distance_km(c.lat[:-1, 5], c.lon[:-1, 5], c.lat[1:, 5], c.lon[1:, 5])
    assert across == pytest.approx(20 * 1.852, rel=1e-9)
    along = geo.distance_km(track[:-1, 0], track[:-1, 1], track[1:, 0], track[1:, 1])
    assert along == pytest.approx(c.leg_km, rel=1e-9)


def test_calm_sea_route_is_the_great_circle(pacific):
    r = pacific.route()
    assert r.pixels[:, 0].tolist() == [10] * 38
    assert r.length / 1.852 == pytest.approx(4443.0, abs=0.5) and r.cost == pytest.approx(r.length)
    legs = r.legs(speed_kn=10)
    assert len(legs) == 37 and legs[0].course == pytest.approx(302.9, abs=0.05)
    assert sum(leg.time_h for leg in legs) == pytest.approx(444.3, abs=0.1)
    assert all(leg.distance_nm == pytest.approx(120.08, abs=0.01) for leg in legs)


def _storm(lat, lon):
    """Impassable (wind > 25 m/s, paper 001) in a box on the great circle near 48 N 170 W."""
    return np.where((np.abs(lat - 48) < 3) & (np.abs(geo.wrap_lon(lon) + 170) < 8), np.inf, 1.0)


@pytest.mark.parametrize("steps", ["forward", "stencil"])
def test_storm_detour(pacific, steps):
    r = pacific.route(_storm, steps=steps, neighbourhood=5)
    assert r.pixels[0].tolist() == [10, 0] and r.pixels[-1].tolist() == [10, 37]
    assert 4445 < r.length / 1.852 < 4500
    assert np.all(np.isfinite(_storm(r.coords[:, 0], r.coords[:, 1])))
    if steps == "stencil":
        fit = r.stats.corridor
        assert fit.planar_length_error < 0.01
        # the same path priced with planar lengths: each step off by at most that error
        assert abs(fit.planar_cost - r.cost) <= fit.planar_length_error * r.cost
        assert fit.planar_cost != r.cost and r.stats.search.settled > 0
    else:
        assert np.all(np.abs(np.diff(r.pixels[:, 1])) == 1)  # layer to next layer only
        assert r.stats.search is None and r.stats.corridor is None  # dynamic programming


def test_environment_from_a_dataarray(pacific):
    lat, lon = np.arange(60.0, 20.0, -0.5), np.arange(0.0, 360.0, 0.5)
    u = np.ones((lat.size, lon.size))
    u[np.ix_((lat > 45) & (lat < 51), (lon > 182) & (lon < 198))] = np.nan  # 178-162 W
    da = xr.DataArray(u, dims=("lat", "lon"), coords={"lat": lat, "lon": lon})
    r = pacific.route(da)
    assert r.length / 1.852 > 4445
    assert np.all(np.isfinite(pacific.sample(da, r.coords[:, 0], r.coords[:, 1])))


def test_blocked_corridor_raises(pacific):
    with pytest.raises(NoRouteError, match="widen the corridor"):
        pacific.route(lambda lat, lon: np.where(np.abs(geo.wrap_lon(lon) + 150) < 2, np.inf, 1.0))
