"""A season on a projected grid with a CF grid mapping (issue 30): OpenSeason, od_matrix and
route_voyages take lat/lon ends, routed on the grid's own km, and every output is in degrees.
A synthetic polar stereographic season (a wall of ice that clears on day 2, so the ship waits),
checked against pyproj worked independently of seaway's projection code."""

from __future__ import annotations

import csv
import dataclasses
import json
import re

import numpy as np
import pytest

import seaway
from seaway.errors import SeawayError
from seaway.fleet import od_matrix, route_voyages
from seaway.icenav import route_season
from seaway.output import export
from support.seasons import POLAR, projected_season

pyproj = pytest.importorskip("pyproj")
TO_M = pyproj.Transformer.from_crs("EPSG:4326", POLAR, always_xy=True)
TO_LL = pyproj.Transformer.from_crs(POLAR, "EPSG:4326", always_xy=True)
DX_KM = 10.0


def _latlon(ds, row, col, dy_km=0.0, dx_km=0.0):
    """(lat, lon) of a point dy/dx km from the centre of pixel (row, col), by pyproj."""
    x = float(ds.x[col]) + 1000 * dx_km
    y = float(ds.y[row]) + 1000 * dy_km
    lon, lat = TO_LL.transform(x, y)
    return float(lat), float(lon)


def _km(lat, lon):
    x, y = TO_M.transform(np.asarray(lon), np.asarray(lat))
    return np.asarray(y) / 1000.0, np.asarray(x) / 1000.0


@pytest.fixture(scope="module")
def opened(tmp_path_factory):
    ds = projected_season()
    path = tmp_path_factory.mktemp("projseason") / "polar.nc"
    ds.to_netcdf(path)
    # Ends 3 and 4 km off the centres of pixels (15, 5) and (15, 45): west and east of the wall.
    start, end = _latlon(ds, 15, 5, 3.0, -4.0), _latlon(ds, 15, 45, -4.0, 3.0)
    return ds, seaway.open_season(str(path)), start, end


def test_lat_lon_ends_on_a_projected_season_route_in_degrees_with_the_wait(opened, tmp_path):
    ds, season, start, end = opened
    assert season.projection is not None and any("projected season" in n for n in season.notes)
    r = season.route(start, end, vessel="Arc4")
    # The ends used: the pixels holding the asked points, within half a pixel of them in km.
    assert r.pixels[0].tolist() == [15, 5] and r.pixels[-1].tolist() == [15, 45]
    for used, asked in ((r.coords[0], start), (r.coords[-1], end)):
        (uy, ux), (ay, ax) = _km(*used), _km(*asked)
        assert abs(uy - ay) <= DX_KM / 2 + 1e-6 and abs(ux - ax) <= DX_KM / 2 + 1e-6
    assert r.requested == (start, end)
    # The route's vertices in degrees are pyproj's of its km vertices (the planar chart's y/x).
    km = dataclasses.replace(r, latlon=None).coords
    lon, lat = TO_LL.transform(km[:, 1] * 1000, km[:, 0] * 1000)
    assert np.allclose(r.coords, np.column_stack([lat, lon]), atol=1e-9)
    assert np.all(
        (r.coords[:, 0] > 70) & (r.coords[:, 0] < 80) & (r.coords[:, 1] > 50) & (r.coords[:, 1] < 70)
    )
    # The ship waits west of the wall until it clears at 48 h; its wait is placed in degrees.
    (wait,) = r.stats.voyage.waits
    since_h = (wait.since - np.datetime64("2026-07-01T00")) / np.timedelta64(1, "h")
    assert since_h + wait.hours == pytest.approx(48.0, abs=1e-3) and wait.hours > 30
    assert wait.position == pytest.approx(_latlon(ds, *wait.pixel), abs=1e-9)
    # The same route given in (row, col) pixels on the same grid: the same hours.
    by_pixel = route_season(season.grid, (15, 5), (15, 45), ice_class="Arc4", v0_kn=12.0)
    assert r.cost == pytest.approx(by_pixel.cost, rel=1e-12)
    # CSV, GeoJSON and GPX carry the vertices in degrees (every vertex is a waypoint).
    paths = [tmp_path / f"r.{ext}" for ext in ("csv", "geojson", "gpx")]
    for p in paths:
        export.write(r, p)
    text = [line for line in paths[0].read_text().splitlines() if not line.startswith("#")]
    rows = list(csv.DictReader(text))
    got = np.array([[float(row["lat"]), float(row["lon"])] for row in rows])
    assert got.shape == r.coords.shape and np.allclose(got, r.coords, atol=1e-6)
    feature = json.loads(paths[1].read_text())
    assert "crs" not in feature  # WGS 84, RFC 7946's
    line = np.array(feature["geometry"]["coordinates"])[:, ::-1]
    assert np.allclose(line, r.coords, atol=1e-9)
    assert feature["properties"]["requested_start"] == pytest.approx(list(start))
    gpx = np.array(re.findall(r'lat="([-\d.]+)" lon="([-\d.]+)"', paths[2].read_text()), float)
    assert np.allclose(gpx[: len(r.coords)], r.coords, atol=1e-6)


def test_arrival_field_od_matrix_and_route_voyages_take_lat_lon_ports(opened):
    ds, season, start, end = opened
    field = season.arrival_field(start, vessel="Arc4")
    engine = season.route(start, end, vessel="Arc4", smooth=False)
    assert float(field.values[15, 45]) == pytest.approx(engine.cost, rel=1e-9)
    assert float(field.values[15, 5]) == 0.0
    table = od_matrix(season, {"W": start, "E": end}, vessel="Arc4")
    assert table.loc["W", "E"] == pytest.approx(engine.cost, rel=1e-9)
    assert table.loc["E", "W"] == pytest.approx(float(season.arrival_field(end, vessel="Arc4").values[15, 5]))
    with pytest.raises(SeawayError, match=r"port far .* lies outside the chart"):
        od_matrix(season, {"W": start, "far": (60.0, 0.0)}, vessel="Arc4")
    smooth = season.route(start, end, vessel="Arc4")
    rows = route_voyages(
        season, {"across": (start, end), "off": (start, (60.0, 0.0))}, vessels=["Arc4"], threads=1
    )
    ok = rows.set_index("voyage").loc["across"]
    assert ok.status == "ok" and ok.hours == pytest.approx(smooth.cost, rel=1e-12)
    assert (ok.used_start_lat, ok.used_start_lon) == pytest.approx(tuple(smooth.coords[0]), abs=1e-9)
    assert ok.wait_h == pytest.approx(smooth.stats.voyage.hours_waiting)
    off = rows.set_index("voyage").loc["off"]
    assert off.status == "bad input" and off.cause == "off chart"


def test_a_season_end_off_the_projected_grid_names_its_corners(opened):
    _, season, start, _ = opened
    with pytest.raises(
        SeawayError, match=r"end 60,0 lies outside the chart \(its corners are at .* lat,lon\)"
    ):
        season.route(start, (60.0, 0.0), vessel="Arc4")
