"""Tiny charts whose least costs and routes are worked out by hand (arithmetic in comments).

Planar charts: a step (di, dj) has length r = sqrt((di*dy)^2 + (dj*dx)^2), and costs
"max": max(u_a, u_b)*r, "mean": (u_a + u_b)/2*r, "integral": the line integral of u along it.
"""

import math

import numpy as np
import pytest

import seaway

S2, S5 = math.sqrt(2), math.sqrt(5)
R_EARTH = 6371.0088


def hav(lat1, lon1, lat2, lon2):
    """Great-circle distance in km, written out independently of seaway."""
    p1, p2 = math.radians(lat1), math.radians(lat2)
    a = (
        math.sin((p2 - p1) / 2) ** 2
        + math.cos(p1) * math.cos(p2) * math.sin(math.radians(lon2 - lon1) / 2) ** 2
    )
    return 2 * R_EARTH * math.asin(math.sqrt(a))


# --- 1 x N corridors ---------------------------------------------------------------------------


@pytest.mark.parametrize(
    "edge_cost, expected",
    [
        ("max", 9.0),  # max(1,2) + max(2,3) + max(3,4) = 2 + 3 + 4
        ("mean", 7.5),  # 1.5 + 2.5 + 3.5
        ("integral", 7.5),  # a unit axis step is half in each pixel: same as the mean
    ],
)
def test_corridor_unit_steps(edge_cost, expected):
    c = np.array([[1.0, 2, 3, 4]])
    r = seaway.route(c, (0, 0), (0, 3), neighbourhood=3, edge_cost=edge_cost)
    assert r.cost == pytest.approx(expected, abs=1e-12)
    assert r.pixels.tolist() == [[0, 0], [0, 1], [0, 2], [0, 3]]
    assert r.length == pytest.approx(3.0)


def test_corridor_long_step_over_expensive_pixel():
    # k=5 allows the step (0,0)->(0,2) of length 2 over the passable pixel worth 10.
    c = np.array([[1.0, 10, 1]])
    # max: max(1,1)*2 = 2 beats max(1,10) + max(10,1) = 20; mean: (1+1)/2*2 = 2 beats 11
    for edge_cost in ("max", "mean"):
        r = seaway.route(c, (0, 0), (0, 2), edge_cost=edge_cost)
        assert r.cost == pytest.approx(2.0)
        assert r.pixels.tolist() == [[0, 0], [0, 2]]
    # integral: the step spends 1/4, 1/2, 1/4 of its length in the pixels:
    # (0.25*1 + 0.5*10 + 0.25*1)*2 = 11 = two unit steps (0.5*1 + 0.5*10)*1 * 2 (a tie)
    assert seaway.route(c, (0, 0), (0, 2), edge_cost="integral").cost == pytest.approx(11.0)
    # with k=3 only unit steps exist: max costs 10 + 10 = 20
    assert seaway.route(c, (0, 0), (0, 2), neighbourhood=3).cost == pytest.approx(20.0)


# --- the segment land rule -----------------------------------------------------------------------


def test_corner_touching_land_blocks_the_diagonal():
    # . is water (cost 1), L land.   L . .      start S=(1,0), end E=(0,1)
    #                                S L .      The diagonal S->E passes the corner shared by
    #                                . . .      the two land pixels: forbidden. Every diagonal
    # through a corner of the land pixel (1,1) is forbidden too, so the route walks round the
    # rim with 6 unit steps, cost 6.
    cost = np.ones((3, 3))
    land = np.zeros((3, 3), bool)
    land[0, 0] = land[1, 1] = True
    r = seaway.route(cost, (1, 0), (0, 1), land=land, neighbourhood=3)
    assert r.cost == pytest.approx(6.0)
    assert r.pixels.tolist() == [[1, 0], [2, 0], [2, 1], [2, 2], [1, 2], [0, 2], [0, 1]]
    # larger stencils find no shortcut: every longer step touches a land square
    for k in (5, 7):
        r = seaway.route(cost, (1, 0), (0, 1), land=land, neighbourhood=k)
        assert r.cost == pytest.approx(6.0)
    # inf in the cost acts as land
    c2 = np.where(land, np.inf, 1.0)
    assert seaway.route(c2, (1, 0), (0, 1), neighbourhood=3).cost == pytest.approx(6.0)
    # without the land, the diagonal costs sqrt(2)
    assert seaway.route(cost, (1, 0), (0, 1), neighbourhood=3).cost == pytest.approx(S2)


def test_start_boxed_in_by_a_corner_pair():
    # S L .   the only way out of S is the diagonal between the two land pixels: no route
    # L . .
    cost = np.ones((3, 3))
    cost[0, 1] = cost[1, 0] = np.nan
    with pytest.raises(seaway.NoRouteError, match="no route from start pixel"):
        seaway.route(cost, (0, 0), (2, 2))


def test_wall_with_a_gap():
    # 5x5 water, land in column 2 at rows 0-3: the only gap is (4,2). k=3, cost 1.
    # (0,0)->(4,1): 3 axis steps + 1 diagonal = 3 + sqrt2 (no diagonal may touch the wall, so
    # the diagonal lies in columns 0-1); (4,1)->(4,2)->(4,3): 2; (4,3)->(0,4): 3 + sqrt2 again.
    cost = np.ones((5, 5))
    cost[:4, 2] = np.inf
    r = seaway.route(cost, (0, 0), (0, 4), neighbourhood=3)
    assert r.cost == pytest.approx(8 + 2 * S2)
    path = [tuple(p) for p in r.pixels]
    assert (4, 2) in path
    assert all(c != 2 for (row, c) in path if row < 4)
    # every step stays in the stencil
    assert np.abs(np.diff(r.pixels, axis=0)).max() == 1


def test_long_step_never_jumps_over_land():
    # row 0: 1 1 1 1 1      start (1,1), end (1,3), k=5. The step (0,2) along row 1 crosses
    # row 1: 1 1 L 1 1      the land pixel (1,2). Diagonals/knight steps from (1,1) touch the
    # land square's corner or edge. So: up 1, along row 0 by 2, down 1 = 4.
    cost = np.ones((2, 5))
    land = np.zeros((2, 5), bool)
    land[1, 2] = True
    r = seaway.route(cost, (1, 1), (1, 3), land=land)
    assert r.cost == pytest.approx(4.0)
    assert r.pixels[0].tolist() == [1, 1] and r.pixels[-1].tolist() == [1, 3]
    assert all(row == 0 for row, _ in r.pixels[1:-1])
    # a passable but costly pixel instead of land may be stepped over: max(1,1)*2 = 2
    cost[1, 2] = 10
    r = seaway.route(cost, (1, 1), (1, 3))
    assert r.cost == pytest.approx(2.0)
    assert r.pixels.tolist() == [[1, 1], [1, 3]]


# --- a knight move under the three edge costs ------------------------------------------------


@pytest.mark.parametrize(
    "edge_cost, expected, path",
    [
        # knight step (1,1)->(2,3): r = sqrt5 -> max(1,3)*sqrt5 = 6.708; but via (1,2):
        # max(1,2)*1 + max(2,3)*sqrt2 = 2 + 3 sqrt2 = 6.243 is cheaper
        ("max", 2 + 3 * S2, [[1, 1], [1, 2], [2, 3]]),
        # knight (1+3)/2*sqrt5 = 2 sqrt5 = 4.472; via (1,2): 1.5 + 2.5 sqrt2 = 5.036
        ("mean", 2 * S5, [[1, 1], [2, 3]]),
        # the knight segment spends 1/4 of its length in each of (1,1), (1,2), (2,2), (2,3):
        # (1+2+3+3)/4*sqrt5 = 2.25 sqrt5 = 5.0312; via (1,2): 0.5*(1+2) + sqrt2*(2+3)/2 = 5.0355
        # (the diagonal only grazes the corner of (1,3) and (2,2): zero length in them)
        ("integral", 2.25 * S5, [[1, 1], [2, 3]]),
    ],
)
def test_knight_step_edge_costs(edge_cost, expected, path):
    u = np.full((5, 5), 100.0)
    u[1, 1], u[1, 2], u[2, 2], u[2, 3] = 1, 2, 3, 3
    r = seaway.route(u, (1, 1), (2, 3), edge_cost=edge_cost, neighbourhood=5)
    assert r.cost == pytest.approx(expected, rel=1e-12)
    assert r.pixels.tolist() == path
    for method in ("dijkstra", "astar"):
        assert seaway.route(u, (1, 1), (2, 3), edge_cost=edge_cost, method=method).cost == pytest.approx(
            expected
        )


def test_anisotropic_cells():
    # dx=2 (columns), dy=1 (rows): a diagonal is sqrt(1 + 4) = sqrt5 long.
    # (0,0)->(2,2): two diagonals 2 sqrt5 = 4.47 beat 2*1 + 2*2 = 6 and sqrt5 + 3 = 5.24
    c = np.ones((3, 3))
    r = seaway.route(c, (0, 0), (2, 2), dx=2, dy=1, neighbourhood=3)
    assert r.cost == pytest.approx(2 * S5)
    assert r.pixels.tolist() == [[0, 0], [1, 1], [2, 2]]
    assert r.length == pytest.approx(2 * S5)
    assert r.coords.tolist() == [[0, 0], [1, 2], [2, 4]]  # (y, x) = (row*dy, col*dx)
    # along a column costs dy per step, along a row dx per step
    assert seaway.route(c, (0, 0), (2, 0), dx=2, dy=1).cost == pytest.approx(2.0)
    assert seaway.route(c, (0, 0), (0, 2), dx=2, dy=1).cost == pytest.approx(4.0)
    assert seaway.route(3 * c, (0, 0), (0, 2), dx=2, dy=1).cost == pytest.approx(12.0)


def test_start_equals_end():
    c = np.ones((3, 4))
    r = seaway.route(c, (1, 2), (1, 2))
    assert r.cost == 0.0
    assert r.pixels.tolist() == [[1, 2]]
    assert r.length == 0.0
    gj = r.to_geojson()
    assert gj["geometry"]["type"] == "LineString"
    assert gj["geometry"]["coordinates"] == [[2.0, 1.0], [2.0, 1.0]]  # [x, y], doubled
    assert gj["properties"]["cost"] == 0.0 and gj["properties"]["length"] == 0.0


def test_walled_off_raises_no_route_error():
    cost = np.ones((3, 3))
    land = np.zeros((3, 3), bool)
    land[:, 1] = True
    with pytest.raises(seaway.NoRouteError, match="check the land mask, or choose another end point") as ei:
        seaway.route(cost, (0, 0), (0, 2), land=land)
    assert isinstance(ei.value, ValueError)
    assert "pixel (0, 0)" in str(ei.value) and "pixel (0, 2)" in str(ei.value)


# --- cost_field --------------------------------------------------------------------------------


def test_cost_field_values():
    # corridor, k=3, max: 0, max(1,2)=2, 2+3=5, 5+4=9
    f = seaway.cost_field(np.array([[1.0, 2, 3, 4]]), (0, 0), neighbourhood=3)
    np.testing.assert_allclose(f, [[0, 2, 5, 9]])
    # from the far end, mean: (4+3)/2 = 3.5, 3.5 + (3+2)/2 = 6, 6 + (2+1)/2 = 7.5
    f = seaway.cost_field(np.array([[1.0, 2, 3, 4]]), (0, 3), neighbourhood=3, edge_cost="mean")
    np.testing.assert_allclose(f, [[7.5, 6.0, 3.5, 0]])
    # 2x3 uniform 2 with dx=3: axis steps 2*3 = 6 (row) and 2*1 = 2 (col), diagonal 2*sqrt10
    f = seaway.cost_field(np.full((2, 3), 2.0), (0, 0), dx=3, dy=1, neighbourhood=3)
    np.testing.assert_allclose(f, [[0, 6, 12], [2, 2 * math.sqrt(10), 6 + 2 * math.sqrt(10)]])
    # unreachable pixels are inf, impassable ones too
    c = np.array([[1.0, np.inf, 1.0], [1.0, np.inf, 1.0]])
    f = seaway.cost_field(c, (1, 0), neighbourhood=5)
    np.testing.assert_array_equal(f, [[1.0, np.inf, np.inf], [0.0, np.inf, np.inf]])


# --- Route attributes on a geographic chart ---------------------------------------------------


def test_geographic_route_length_coords_geojson():
    lat, lon = [10.0, 11.0], [20.0, 21.0, 22.0]
    c = np.full((2, 3), 2.0)
    # with k=5 the single step (1,2) is the great circle between the two centres: the shortest
    r = seaway.route(c, (10, 20), (11, 22), lat=lat, lon=lon)
    d = hav(10, 20, 11, 22)
    # flat-earth check: sqrt(111.2^2 + (2*111.2*cos 10.5deg)^2) = 245.3 km
    assert d == pytest.approx(245.3, abs=0.1)
    assert r.pixels.tolist() == [[0, 0], [1, 2]]
    assert r.coords.tolist() == [[10, 20], [11, 22]]
    assert r.length == pytest.approx(d, rel=1e-9)
    assert r.cost == pytest.approx(2 * d, rel=1e-9)
    gj = r.to_geojson()
    assert gj["type"] == "Feature"
    assert gj["geometry"] == {"type": "LineString", "coordinates": [[20.0, 10.0], [22.0, 11.0]]}
    assert gj["properties"]["cost"] == pytest.approx(2 * d)
    assert gj["properties"]["length"] == pytest.approx(d)
    assert gj["properties"]["length_units"] == "km"


def test_every_steps_length_is_the_haversine_of_its_ends():
    """The engine's table of step lengths (each row's trigonometry read from tables while the
    chart is prepared) against the haversine of the two pixel centres, for every step of a 7 x 7
    stencil from every row of a chart from 60 S to the pole, across the antimeridian (wrap)."""
    lat, lon = np.arange(-60.0, 90.01, 7.5), np.arange(0.0, 360.0, 10.0)
    chart = seaway.prepare(np.ones((lat.size, lon.size)), lat=lat, lon=lon, neighbourhood=7)
    for r in range(lat.size):
        for di in range(-3, 4):
            for dj in range(-3, 4):
                if (di, dj) == (0, 0) or not 0 <= r + di < lat.size:
                    continue
                c1 = (35 + dj) % lon.size  # over the seam: column 35 is 350 E
                route = chart.route((lat[r], lon[35]), (lat[r + di], lon[c1]), method="dijkstra")
                want = hav(lat[r], lon[35], lat[r + di], lon[c1])
                if len(route.pixels) == 2:  # the single step (a cheaper pair of steps may exist)
                    assert route.length == pytest.approx(want, rel=1e-12, abs=1e-9), (r, di, dj)
                assert route.length <= want * (1 + 1e-12) + 1e-9


def test_geographic_equator_km():
    # along the equator one degree is R*pi/180 = 111.195 km; k=3: two steps, cost 1 each km
    r = seaway.route(np.ones((1, 3)), (0, 0), (0, 2), lat=[0.0], lon=[0.0, 1.0, 2.0], neighbourhood=3)
    km = R_EARTH * math.pi / 180
    assert km == pytest.approx(111.195, abs=1e-3)
    assert r.cost == pytest.approx(2 * km, rel=1e-12)
    assert r.length == pytest.approx(2 * km, rel=1e-12)
    assert r.coords.tolist() == [[0, 0], [0, 1], [0, 2]]
    # the line through its waypoints (the ends; no course change), as every export gives it
    assert r.to_geojson()["geometry"]["coordinates"] == [[0, 0], [2, 0]]


def test_planar_geojson_is_x_y():
    r = seaway.route(np.ones((3, 3)), (0, 0), (2, 1), dx=10, dy=5, neighbourhood=3)
    # (0,0)->(1,0)->(2,1) or (0,0)->(1,1)->(2,1): 5 + sqrt(125), either way
    assert r.cost == pytest.approx(5 + math.sqrt(125))
    coords = r.to_geojson()["geometry"]["coordinates"]
    assert coords[0] == [0.0, 0.0] and coords[-1] == [10.0, 10.0]  # [x, y] of (row 2, col 1)
    assert r.to_geojson()["properties"]["length_units"] == "grid units"
