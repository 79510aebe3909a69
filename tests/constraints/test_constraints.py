"""Keep-away buffers, polygon zones and via-points (seaway.constraints, PreparedChart.route):
distances against brute force, factors by hand, routes that obey them."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway.chart.raster import as_chart
from seaway.constraints import KeepAway, Zone, constrain, distance_to, rasterise_zone
from support.distance import brute_distance

shapely = pytest.importorskip("shapely")
from shapely.geometry import Polygon, box  # noqa: E402


@pytest.mark.parametrize("kind", ["planar", "geo_north", "geo_south_desc", "geo_wrap"])
def test_distance_matches_brute_force(kind):
    rng = np.random.default_rng(len(kind))
    rows, cols = (12, 24) if kind == "geo_wrap" else (15, 18)
    mask = rng.random((rows, cols)) < 0.05
    geo = {}
    if kind == "planar":
        geo = dict(dx=1.7, dy=0.6)
    elif kind == "geo_north":
        geo = dict(lat=70 + 0.25 * np.arange(rows), lon=20 + 0.9 * np.arange(cols))
    elif kind == "geo_south_desc":
        geo = dict(lat=-50 - 0.3 * np.arange(rows), lon=170 + 0.5 * np.arange(cols))  # crosses 180
    else:
        geo = dict(lat=80 - 1.0 * np.arange(rows), lon=-180 + 15.0 * np.arange(cols))
    chart = as_chart(np.ones((rows, cols)), **geo)
    want = brute_distance(mask, geo.get("lat"), geo.get("lon"), geo.get("dx", 1), geo.get("dy", 1))
    limit = float(np.nanmax(want[np.isfinite(want)])) * 0.6
    got = distance_to(mask, chart, limit)
    near = want <= limit
    np.testing.assert_allclose(got[near], want[near], rtol=1e-9, atol=1e-9)
    assert np.isinf(got[~near]).all()


def test_land_buffer_hard_and_soft_factors():
    """Planar 1 x 11 strip, land at column 0, unit pixels: hard 2, soft out to 6, penalty 3:
    factor inf for d <= 2, 1 + 3 (6 - d) / 4 for 2 < d < 6, 1 beyond."""
    u = np.ones((1, 11))
    land = np.zeros((1, 11), bool)
    land[0, 0] = True
    out = constrain(u, land=land, keep_away=KeepAway(km=2, soft_km=6, penalty=3))
    d = np.arange(11.0)
    want = np.where(d <= 2, np.inf, np.where(d < 6, 1 + 3 * (6 - d) / 4, 1.0))
    want[0] = np.inf
    np.testing.assert_allclose(out[0], want)


def test_route_keeps_its_distance_from_land():
    """Lat/lon chart with an island: every pixel of the route lies more than 20 km from land
    (great-circle, by brute force), and the route costs more than the unconstrained one."""
    lat, lon = 70 + 0.05 * np.arange(60), 10 + 0.15 * np.arange(80)
    u = np.ones((60, 80))
    land = np.zeros_like(u, bool)
    land[20:40, 35:45] = True
    kw = dict(lat=lat, lon=lon, land=land, neighbourhood=5)
    a, b = (71.5, 10.0), (71.5, 21.8)
    free = seaway.route(u, a, b, **kw)
    kept = seaway.route(u, a, b, keep_away=KeepAway(km=20), **kw)
    d = brute_distance(land, lat, lon)
    assert d[tuple(free.pixels.T)].min() <= 20
    assert d[tuple(kept.pixels.T)].min() > 20
    assert kept.cost > free.cost


def test_ice_buffer_by_threshold_and_by_mask():
    """Severe ice (cost >= 5) in the middle column: a 1-unit buffer closes its neighbours too;
    the same via a boolean DataArray mask."""
    u = np.ones((9, 9))
    u[2:7, 4] = 6.0
    by_cost = constrain(u, keep_away=KeepAway(km=1, ice=5))
    assert np.isinf(by_cost[2:7, 3:6]).all() and np.isinf(by_cost[1, 4]) and np.isinf(by_cost[7, 4])
    assert np.isfinite(by_cost[0]).all() and by_cost[1, 3] == 1.0
    da = xr.DataArray(u, dims=("y", "x"), coords={"y": np.arange(9.0), "x": np.arange(9.0)})
    by_mask = constrain(da, keep_away=KeepAway(km=1, ice=da >= 5))
    assert isinstance(by_mask, xr.DataArray)
    np.testing.assert_array_equal(by_mask.values, by_cost)


def test_zone_rasterised_by_pixel_centre():
    lat, lon = 60 + 0.5 * np.arange(10), 0 + 1.0 * np.arange(12)
    chart = as_chart(np.ones((10, 12)), lat=lat, lon=lon)
    zone = Zone(box(2.5, 61.0, 6.0, 62.2))  # lon 3..6 inclusive (6 on the edge), lat 61, 61.5, 62
    got = rasterise_zone(zone, chart)
    want = np.zeros((10, 12), bool)
    want[2:5, 3:7] = True
    np.testing.assert_array_equal(got, want)
    # the same zone given in -180..180 on a 0..360 chart
    chart360 = as_chart(np.ones((10, 12)), lat=lat, lon=350 + np.arange(12.0))
    west = Zone(box(-8.5, 61.0, -5.0, 62.2))  # lon 351.5..355 -> columns 2..5
    want360 = np.zeros((10, 12), bool)
    want360[2:5, 2:6] = True
    np.testing.assert_array_equal(rasterise_zone(west, chart360), want360)


def test_exclusion_and_penalty_zones_on_a_route(tmp_path):
    """Planar 11 x 21 sea: a wall zone with a gap. Excluded, the route goes through the gap;
    as a penalty x3 across the whole band the straight route costs 20 + 2 x 2 (three pixels
    of the band at factor 3 with the max edge cost)."""
    u = np.ones((11, 21))
    wall = Polygon([(9.5, -1), (11.5, -1), (11.5, 8.5), (9.5, 8.5)])  # x = col, y = row
    r = seaway.route(u, (2, 0), (2, 20), zones=[Zone(wall)], neighbourhood=3)
    assert (r.pixels[:, 0] >= 9).any() and not (
        (r.pixels[:, 1] >= 10) & (r.pixels[:, 1] <= 11) & (r.pixels[:, 0] <= 8)
    ).any()
    band = box(9.5, -1, 11.5, 12)
    path = tmp_path / "band.geojson"
    path.write_text(
        json.dumps(
            {
                "type": "FeatureCollection",
                "features": [
                    {"type": "Feature", "properties": {}, "geometry": shapely.geometry.mapping(band)}
                ],
            }
        )
    )
    p = seaway.route(u, (2, 0), (2, 20), zones=[Zone(str(path), penalty=3)], neighbourhood=3, edge_cost="max")
    assert p.cost == pytest.approx(20 + 3 * 2)  # steps 9->10, 10->11, 11->12 at 3 instead of 1
    assert p.pixels[:, 0].tolist() == [2] * 21


def test_zone_from_a_shapefile_and_a_geojson_mapping(tmp_path):
    """The same polygon as a shapefile (pyogrio), a GeoJSON mapping and a shapely geometry
    rasterises to the same pixels, and as an exclusion the route detours around it."""
    pyogrio = pytest.importorskip("pyogrio")
    lat, lon = 70 + 0.1 * np.arange(30), 40 + 0.2 * np.arange(40)
    chart = as_chart(np.ones((30, 40)), lat=lat, lon=lon)
    poly = box(43.9, 70.5, 45.1, 72.45)  # columns 20-25, rows 5-24
    path = tmp_path / "closed.shp"
    pyogrio.raw.write(
        str(path),
        np.array([shapely.to_wkb(poly)], dtype=object),
        [],
        [],
        driver="ESRI Shapefile",
        crs="EPSG:4326",
        geometry_type="Polygon",
    )
    masks = [rasterise_zone(Zone(g), chart) for g in (str(path), shapely.geometry.mapping(poly), poly)]
    want = np.zeros((30, 40), bool)
    want[5:25, 20:26] = True
    for m in masks:
        np.testing.assert_array_equal(m, want)
    r = seaway.route(
        np.ones((30, 40)),
        (71.5, 40.0),
        (71.5, 47.8),
        lat=lat,
        lon=lon,
        zones=[Zone(str(path), name="closed area")],
        neighbourhood=5,
    )
    assert not want[tuple(r.pixels.T)].any()
    free = seaway.route(np.ones((30, 40)), (71.5, 40.0), (71.5, 47.8), lat=lat, lon=lon, neighbourhood=5)
    assert want[tuple(free.pixels.T)].any() and r.cost > free.cost


def test_via_points_each_leg_optimal():
    rng = np.random.default_rng(4)
    u = rng.uniform(1, 3, (30, 40))
    chart = seaway.prepare(u, neighbourhood=5)
    a, v1, v2, b = (0, 0), (25, 5), (3, 30), (29, 39)
    r = chart.route(a, b, via=[v1, v2], method="dijkstra")
    legs = [chart.route(p, q, method="dijkstra") for p, q in [(a, v1), (v1, v2), (v2, b)]]
    assert r.cost == pytest.approx(sum(leg.cost for leg in legs), rel=1e-12)
    assert (
        r.pixels.tolist()
        == legs[0].pixels.tolist() + legs[1].pixels[1:].tolist() + legs[2].pixels[1:].tolist()
    )
    assert list(r.stats.constraints.via_pixels) == [v1, v2]
    assert r.stats.constraints.turn_penalty is None
    # the legs' search figures combined: settled adds up, the peaks take the larger
    figures = [leg.stats.search for leg in legs]
    assert r.stats.search.settled == sum(f.settled for f in figures)
    assert r.stats.search.heap_peak == max(f.heap_peak for f in figures)
    assert r.stats.search.state_bytes == max(f.state_bytes for f in figures)
    assert r.cost > chart.route(a, b).cost


def test_via_errors_name_the_point():
    u = np.ones((10, 10))
    u[5, 5] = np.inf
    with pytest.raises(ValueError, match="via point 2 is on an impassable pixel"):
        seaway.route(u, (0, 0), (9, 9), via=[(2, 2), (5, 5)])
    with pytest.raises(TypeError, match="list of points"):
        seaway.route(u, (0, 0), (9, 9), via=(2, 2))


@pytest.mark.parametrize(
    "kwargs,match",
    [
        (dict(km=-1), "km must be"),
        (dict(km=5, soft_km=3), "soft_km"),
        (dict(), "changes nothing"),
        (dict(km=1, ice=np.ones((3, 3))), "boolean"),
    ],
)
def test_bad_keep_away(kwargs, match):
    with pytest.raises((ValueError, TypeError), match=match):
        constrain(np.ones((4, 4)), keep_away=KeepAway(**kwargs))


def test_bad_zone():
    with pytest.raises(ValueError, match="penalty must be >= 1"):
        Zone(box(0, 0, 1, 1), penalty=0.5)
    with pytest.raises(ValueError, match="no area"):
        constrain(np.ones((4, 4)), zones=Zone(shapely.geometry.LineString([(0, 0), (1, 1)])))
    with pytest.raises(TypeError, match="geometry must be"):
        constrain(np.ones((4, 4)), zones=Zone(42))
    assert math.isinf(Zone(box(0, 0, 1, 1)).penalty)


def test_route_many_with_constraints():
    """route_many passes buffers, zones, the turn penalty and per-voyage via points: each row
    costs what seaway.route gives with the same constraints."""
    pytest.importorskip("pandas")
    rng = np.random.default_rng(8)
    u = rng.uniform(1, 2, (30, 40))
    u[10:20, 15:25] = np.inf
    keep, zone = KeepAway(km=2, soft_km=5, penalty=1), Zone(box(30, 0, 33, 20), penalty=4)
    voyages = {"plain": ((2, 2), (27, 37)), "via": ((2, 2), (27, 37), [(25, 5)])}
    table = seaway.route_many(
        u, voyages, threads=2, keep_away=[keep], zones=[zone], turn_penalty=0.01, keep_routes=True
    )
    assert table.status.tolist() == ["ok", "ok"]
    for vid, (s, e, *via) in voyages.items():
        want = seaway.route(
            u, s, e, via=via[0] if via else (), keep_away=[keep], zones=[zone], turn_penalty=0.01
        )
        row = table.set_index("voyage").loc[vid]
        assert row.cost == pytest.approx(want.cost, rel=1e-12)
        assert row.route.pixels.tolist() == want.pixels.tolist()
    assert [25, 5] in table.route[1].pixels.tolist()


@pytest.mark.cli
def test_cli_constraints(tmp_path):
    """`seaway route` with --via, --turn-penalty, --land-buffer, --land-soft, --ice-buffer and
    --penalty-zone gives the API's route with the same constraints."""
    import subprocess
    import sys

    lat, lon = np.linspace(76.0, 70.0, 61), np.linspace(60.0, 76.0, 81)
    cost = np.ones((61, 81))
    cost[45:, :] = 8.0
    land = np.zeros((61, 81), bool)
    land[10:35, 30:45] = True
    ds = xr.Dataset(
        {"cost": (("lat", "lon"), cost), "land": (("lat", "lon"), land)}, coords={"lat": lat, "lon": lon}
    )
    path = tmp_path / "c.nc"
    ds.to_netcdf(path)
    zone = tmp_path / "z.geojson"
    zone.write_text(
        json.dumps({"type": "Polygon", "coordinates": [[[66, 73], [68, 73], [68, 75], [66, 75], [66, 73]]]})
    )
    out = tmp_path / "r.geojson"
    done = subprocess.run(
        [
            sys.executable,
            "-m",
            "seaway",
            "route",
            str(path),
            "--variable",
            "cost",
            "--from",
            "73,61",
            "--to",
            "73,75",
            "--via",
            "75.5,68",
            "--turn-penalty",
            "0.01",
            "--land-buffer",
            "10",
            "--land-soft",
            "30,2",
            "--ice-buffer",
            "8,15",
            "--penalty-zone",
            f"{zone},3",
            "--out",
            str(out),
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 0, done.stderr
    assert "not smoothed" in done.stderr
    want = seaway.route(
        ds.cost,
        (73, 61),
        (73, 75),
        land=ds.land,
        via=[(75.5, 68)],
        turn_penalty=0.01,
        keep_away=[KeepAway(km=10, soft_km=30, penalty=2), KeepAway(km=15, ice=8.0)],
        zones=[Zone(str(zone), penalty=3)],
    )
    assert json.loads(out.read_text())["properties"]["cost"] == pytest.approx(want.cost, rel=1e-9)
    bad = subprocess.run(
        [
            sys.executable,
            "-m",
            "seaway",
            "route",
            str(path),
            "--from",
            "73,61",
            "--to",
            "73,75",
            "--penalty-zone",
            f"{zone},0.5",
        ],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert bad.returncode == 2 and "FACTOR >= 1" in bad.stderr


def test_cost_field_with_a_buffer_and_a_zone():
    """cost_field takes the same buffers and zones: the field of the constrained raster."""
    u = np.ones((12, 15))
    land = np.zeros_like(u, bool)
    land[5:7, 6:8] = True
    keep, zone = KeepAway(km=1.5, soft_km=3, penalty=2), Zone(box(10.5, -1, 12.5, 6.5), penalty=3)
    got = seaway.cost_field(u, (0, 0), land=land, keep_away=[keep], zones=[zone], neighbourhood=3)
    want = seaway.cost_field(
        constrain(u, land=land, keep_away=[keep], zones=[zone]), (0, 0), land=land, neighbourhood=3
    )
    np.testing.assert_array_equal(got, want)
    assert np.isinf(got[4, 6]) and np.isfinite(got[11, 14])  # within 1.5 of land; reachable
    plain = seaway.cost_field(u, (0, 0), land=land, neighbourhood=3)
    assert got[0, 14] > plain[0, 14]  # behind the penalty band
