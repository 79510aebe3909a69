"""Every bad input gets a ValueError or TypeError whose message names the fix."""

import numpy as np
import pytest

import seaway

xr = pytest.importorskip("xarray")

C = np.ones((4, 5))
LAT, LON = np.arange(50.0, 54.0), np.arange(0.0, 5.0)


def test_no_route_error_is_a_value_error():
    assert issubclass(seaway.NoRouteError, ValueError)
    c = C.copy()
    c[:, 2] = np.inf
    with pytest.raises(ValueError, match="impassable pixels keep them apart") as e:
        seaway.route(c, (0, 0), (0, 4))
    assert "check the land mask" not in str(e.value)  # a cost of inf, not land, closes the way


# --- start and end ------------------------------------------------------------------------


@pytest.mark.parametrize(
    "start, end, who", [((0, 0), (4, 0), "end"), ((-1, 0), (3, 0), "start"), ((0, 5), (0, 0), "start")]
)
def test_planar_point_outside(start, end, who):
    with pytest.raises(
        ValueError,
        match=rf"{who} .* lies outside the chart .* give a \(row, col\) "
        r"pixel index with 0 <= row < 4 and 0 <= col < 5",
    ):
        seaway.route(C, start, end)
    with pytest.raises(ValueError, match="lies outside the chart"):
        seaway.cost_field(C, end if who == "end" else start)


def test_planar_fractional_point_names_lat_lon():
    with pytest.raises(ValueError, match="pass lat= and lon="):
        seaway.route(C, (0.5, 0), (3, 0))


@pytest.mark.parametrize("start", [(30, 0), (52, 20), (49.4, 0)])
def test_geographic_point_outside(start):
    with pytest.raises(
        ValueError, match=r"start .* lies outside the chart .*give a point on the chart as \(lat, lon\)"
    ):
        seaway.route(C, start, (53, 4), lat=LAT, lon=LON)


def test_row_col_on_geographic_chart_is_outside():
    # (row, col) = (1, 1) read as lat 1, lon 1: off this chart, and the message says (lat, lon)
    with pytest.raises(ValueError, match=r"lat 50 to 53.*\(lat, lon\)"):
        seaway.route(C, (1, 1), (3, 0), lat=LAT, lon=LON)


@pytest.mark.parametrize(
    "point, exc, match",
    [
        ("ab", TypeError, "must be a pair of numbers"),
        ((1, 2, 3), TypeError, "must be a pair of numbers"),
        (None, TypeError, "must be a pair of numbers"),
        ((0, np.nan), ValueError, "must be finite"),
    ],
)
def test_malformed_point(point, exc, match):
    with pytest.raises(exc, match=match):
        seaway.route(C, (0, 0), point)


def test_start_or_end_on_land_names_nearest_passable_pixel():
    c = C.copy()
    c[1:3, 1:3] = np.inf
    with pytest.raises(
        ValueError,
        match=r"start is on an impassable pixel .*pixel \(1, 1\); the "
        r"nearest passable pixel is pixel \(0, 1\)",
    ):
        seaway.route(c, (1, 1), (3, 0))
    with pytest.raises(
        ValueError, match=r"end is on an impassable .*nearest passable pixel is pixel \(2, 3\)"
    ):
        seaway.route(c, (0, 0), (2, 2))
    land = np.zeros_like(C, bool)
    land[3, 4] = True
    with pytest.raises(
        ValueError, match=r"end is on .*pixel \(3, 4\); the nearest passable pixel is pixel \(2, 4\)"
    ):
        seaway.route(C, (0, 0), (3, 4), land=land)
    # on a geographic chart the message gives lat/lon too
    with pytest.raises(
        ValueError, match=r"nearest passable pixel is pixel \(0, 1\) at lat 50.0000, lon 1.0000"
    ):
        seaway.route(c, (51, 1), (53, 0), lat=LAT, lon=LON)
    with pytest.raises(ValueError, match="start is on an impassable pixel"):
        seaway.cost_field(c, (1, 1))


def test_all_land():
    c = np.full((2, 2), np.nan)
    with pytest.raises(ValueError, match="no pixel of the chart is passable"):
        seaway.route(c, (0, 0), (1, 1))


# --- cost values, shapes and dtypes --------------------------------------------------------


def test_negative_cost():
    c = C.copy()
    c[2, 3] = -0.5
    with pytest.raises(
        ValueError, match=r"-0.5 at pixel \(2, 3\); costs must be >= 0: mark impassable pixels with np.inf"
    ):
        seaway.route(c, (0, 0), (3, 0))
    with pytest.raises(ValueError, match="costs must be >= 0"):
        seaway.cost_field(c, (0, 0))


def test_land_shape_mismatch():
    with pytest.raises(
        ValueError,
        match=r"land has shape \(5, 4\) but cost has shape \(4, 5\); give a mask of the same shape",
    ):
        seaway.route(C, (0, 0), (3, 0), land=np.zeros((5, 4), bool))


def test_lat_lon_length_mismatch():
    with pytest.raises(ValueError, match="give one latitude per row and one longitude per column"):
        seaway.route(C, (50, 0), (53, 0), lat=np.arange(5.0), lon=LON)
    with pytest.raises(ValueError, match="give one latitude per row and one longitude per column"):
        seaway.route(C, (50, 0), (53, 0), lat=LAT, lon=np.arange(4.0))
    with pytest.raises(ValueError, match="give both lat and lon"):
        seaway.route(C, (50, 0), (53, 0), lat=LAT)


@pytest.mark.parametrize("bad", ["lat", "lon", "y"])
def test_irregular_spacing(bad):
    msg = rf"{bad} is not regularly spaced .*resample the chart onto a regular grid"
    if bad == "y":
        da = xr.DataArray(C, dims=("y", "x"), coords={"y": [0, 1, 3, 4.0], "x": np.arange(5.0)})
        with pytest.raises(ValueError, match=msg):
            seaway.route(da, (0, 0), (3, 0))
        return
    lat, lon = LAT.copy(), LON.copy()
    (lat if bad == "lat" else lon)[2] += 0.3
    with pytest.raises(ValueError, match=msg):
        seaway.route(C, (50, 0), (53, 0), lat=lat, lon=lon)


@pytest.mark.parametrize("bad", ["lat", "lon"])
def test_nan_in_coordinates(bad):
    lat, lon = LAT.copy(), LON.copy()
    (lat if bad == "lat" else lon)[1] = np.nan
    with pytest.raises(
        ValueError, match=rf"{bad} holds NaN or infinite values; give the pixel-centre coordinates"
    ):
        seaway.route(C, (50, 0), (53, 0), lat=lat, lon=lon)
    da = xr.DataArray(C, dims=("lat", "lon"), coords={"lat": lat, "lon": lon})
    with pytest.raises(ValueError, match="holds NaN or infinite values"):
        seaway.cost_field(da, (50, 0))


def test_coordinates_out_of_range():
    with pytest.raises(ValueError, match=r"lat must lie within \[-90, 90\]"):
        seaway.route(C, (88, 0), (89, 0), lat=LAT + 38, lon=LON)
    with pytest.raises(ValueError, match="a chart covers at most 360 degrees of longitude"):
        seaway.route(np.ones((2, 40)), (0, 0), (1, 0), lat=[0.0, 1.0], lon=np.arange(40.0) * 10)


@pytest.mark.parametrize("name, value", [("dx", 0), ("dy", -1.0), ("dx", np.nan), ("dy", np.inf)])
def test_bad_cell_size(name, value):
    with pytest.raises(ValueError, match=rf"{name} must be a positive cell size"):
        seaway.route(C, (0, 0), (3, 0), **{name: value})


def test_not_2d():
    with pytest.raises(
        ValueError, match=r"cost must be a 2-D raster, got shape \(2, 3, 4\); give one \(rows, cols\) layer"
    ):
        seaway.route(np.ones((2, 3, 4)), (0, 0), (1, 0))
    with pytest.raises(ValueError, match="must be a 2-D raster"):
        seaway.route(np.ones(4), (0, 0), (0, 1))
    da = xr.DataArray(np.ones((2, 3, 4)), dims=("time", "lat", "lon"))
    with pytest.raises(ValueError, match=r"select one time or level first, e.g. da.isel\(time=0\)"):
        seaway.cost_field(da, (0, 0))


@pytest.mark.parametrize("shape", [(0, 4), (3, 0), (0, 0)])
def test_empty(shape):
    with pytest.raises(ValueError, match="cost is empty .*give at least one pixel"):
        seaway.route(np.ones(shape), (0, 0), (0, 0))


@pytest.mark.parametrize("dtype", [complex, bool, str, object])
def test_bad_dtype(dtype):
    with pytest.raises(TypeError, match=r"cost must hold real numbers, got dtype"):
        seaway.route(C.astype(dtype), (0, 0), (1, 0))


# --- options ------------------------------------------------------------------------------


@pytest.mark.parametrize("k", [4, 2, 1, 17, 0, -3, 16])
def test_bad_neighbourhood_value(k):
    with pytest.raises(
        ValueError, match=r"neighbourhood must be odd and between 3 and 15 .*e.g. neighbourhood=5"
    ):
        seaway.route(C, (0, 0), (3, 0), neighbourhood=k)
    with pytest.raises(ValueError, match="neighbourhood must be odd"):
        seaway.cost_field(C, (0, 0), neighbourhood=k)


@pytest.mark.parametrize("k", [5.0, "5", True, None])
def test_bad_neighbourhood_type(k):
    with pytest.raises(TypeError, match="neighbourhood must be an odd integer from 3 to 15"):
        seaway.route(C, (0, 0), (3, 0), neighbourhood=k)


def test_numpy_int_neighbourhood_is_fine():
    assert seaway.route(C, (0, 0), (3, 0), neighbourhood=np.int64(3)).cost == 3.0


@pytest.mark.parametrize(
    "kw, match",
    [
        (
            {"edge_cost": "min"},
            r"edge_cost must be one of \('max', 'mean', 'integral', 'length'\), got 'min'",
        ),
        ({"edge_cost": "entered"}, "edge_cost must be one of"),
        ({"directions": "diag"}, r"directions must be one of \('full', 'unique'\)"),
        ({"directions": "axis"}, "directions must be one of"),
        (
            {"method": "bfs"},
            r"method must be one of \('auto', 'dijkstra', 'astar', 'bidirectional', 'landmarks'\)",
        ),
        ({"weight": 0.5}, "weight must be a finite number >= 1"),
        ({"weight": np.nan}, "weight must be a finite number >= 1"),
        ({"weight": np.inf}, "weight must be a finite number >= 1"),
        ({"weight": 2.0, "method": "dijkstra"}, "use it with method='astar'"),
    ],
)
def test_bad_options(kw, match):
    with pytest.raises(ValueError, match=match):
        seaway.route(C, (0, 0), (3, 0), **kw)


def test_bad_options_cost_field():
    with pytest.raises(ValueError, match="edge_cost must be one of"):
        seaway.cost_field(C, (0, 0), edge_cost="sum")
    with pytest.raises(ValueError, match="directions must be one of"):
        seaway.cost_field(C, (0, 0), directions="all")


def test_weight_one_and_weighted_astar_bound():
    rng = np.random.default_rng(3)
    c = rng.uniform(1, 3, (30, 30))
    best = seaway.route(c, (0, 0), (29, 29), method="dijkstra").cost
    assert seaway.route(c, (0, 0), (29, 29), weight=1).cost == pytest.approx(best)
    w = seaway.route(c, (0, 0), (29, 29), weight=1.5).cost
    assert best - 1e-9 <= w <= 1.5 * best


# --- arguments named in the error (issue 13) ---------------------------------------------


@pytest.mark.parametrize(
    "kw, name", [({"dx": "1"}, "dx"), ({"dy": [1.0]}, "dy"), ({"dx": True}, "dx"), ({"dx": None}, "dx")]
)
def test_a_non_number_cell_size_is_named(kw, name):
    with pytest.raises(TypeError, match=rf"{name} must be a positive cell size, got \w+ "):
        seaway.route(np.ones((4, 4)), (0, 0), (3, 3), **kw)


def test_every_numeric_argument_is_checked_by_name():
    from seaway.corridor import corridor
    from seaway.samples import synthetic_sea
    from seaway.vessel import Vessel

    u = np.ones((6, 6))
    with pytest.raises(TypeError, match="weight must be a finite number >= 1"):
        seaway.route(u, (0, 0), (5, 5), weight="2")
    with pytest.raises(TypeError, match=r"speed_kn must be positive, got str '12'"):
        Vessel(speed_kn="12").check()
    with pytest.raises(ValueError, match="displacement_t must be a finite number > 0"):
        Vessel(displacement_t=np.nan).check()
    with pytest.raises(TypeError, match="beam_m must be a finite number > 0"):
        Vessel(speed_loss="stawave1", beam_m="20", length_m=100.0, calm_resistance_kn=300.0).check()
    with pytest.raises(TypeError, match="row_nm must be a finite number > 0"):
        corridor((60, 0), (61, 5), spacing_nm=50, row_nm="20")
    with pytest.raises(TypeError, match="m must be a finite integer >= 0"):
        corridor((60, 0), (61, 5), spacing_nm=50, m=2.5)
    with pytest.raises(TypeError, match="threads must be a finite integer >= 1, got str '2'"):
        seaway.route_many(u, [((0, 0), (5, 5))], threads="2")
    with pytest.raises(ValueError, match=r"land_fraction must be a number in \[0, 0.9\)"):
        synthetic_sea((20, 20), land_fraction=np.nan)
    from seaway.models import IceSeasonTime

    with pytest.raises(TypeError, match="v0_kn must be a finite number > 0, got str '12'"):
        IceSeasonTime(None, v0_kn="12")
    r = seaway.route(u, (0, 0), (5, 5))
    with pytest.raises(ValueError, match="speed_kn must be a finite number > 0"):
        r.legs(speed_kn=0)
    assert seaway.route(u, (0, 0), (5, 5), dx=np.float32(2), dy=np.int64(2)).cost == pytest.approx(
        2 * r.cost
    )  # numpy scalars are numbers


@pytest.mark.parametrize("bad", [np.nan, 2.0, 0.5, -1.0])
def test_a_land_mask_that_is_not_0_or_1_is_refused(bad):
    land = np.zeros((5, 5))
    land[2, 3] = bad
    with pytest.raises(
        ValueError,
        match=r"land must hold only 0 \(sea\) and 1 \(land\).*"
        r"pixel \(2, 3\).*give a bool mask",
    ):
        seaway.route(np.ones((5, 5)), (0, 0), (4, 4), land=land)
    with pytest.raises(TypeError, match="land must be a boolean mask"):
        seaway.route(np.ones((5, 5)), (0, 0), (4, 4), land=np.full((5, 5), "0"))
