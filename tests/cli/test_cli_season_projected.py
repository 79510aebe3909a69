"""`seaway season` on MET Norway's ROMS Arctic-20km daily ice (a polar stereographic grid with a
CF grid mapping; issue 30): --from/--to in lat/lon, the outputs in degrees (pyproj's of the
route's km vertices, worked independently), the hours those of the same route given in
(row, col) pixels, and `seaway replan` on the GeoJSON it wrote."""

from __future__ import annotations

import csv
import dataclasses
import json

import numpy as np
import pytest

import seaway
from seaway.cli import main
from seaway.icenav import route_season

pytestmark = [pytest.mark.cli, pytest.mark.needs_data("ocean_model", "metno_ROMS_Arctic20_1to5Feb_2016.nc")]
ROMS = "ocean_model/metno_ROMS_Arctic20_1to5Feb_2016.nc"
PROJ4 = "+proj=stere +a=6371000 +b=6371000 +lat_0=90 +lat_ts=60 +lon_0=58"  # the file's proj4_string
START, END = (68.74, 5.46), (78.87, 39.31)  # open water off Norway; 5-6/10 ice east of Svalbard


def test_roms_season_by_lat_lon_writes_degrees_and_replans(shared_data, tmp_path, capsys):
    pyproj = pytest.importorskip("pyproj")
    to_ll = pyproj.Transformer.from_crs(PROJ4, "EPSG:4326", always_xy=True)
    to_m = pyproj.Transformer.from_crs("EPSG:4326", PROJ4, always_xy=True)
    path = shared_data / ROMS
    season = seaway.open_season(str(path))
    r = season.route(START, END, vessel="Arc4")
    # The ends used: pixels (20, 10) and (33, 80), within half a 20-km pixel of the asked points.
    assert r.pixels[0].tolist() == [20, 10] and r.pixels[-1].tolist() == [33, 80]
    km = dataclasses.replace(r, latlon=None).coords  # the route's vertices in the grid's km
    for (lat, lon), (y, x) in ((START, km[0]), (END, km[-1])):
        ax, ay = to_m.transform(lon, lat)
        assert abs(ay / 1000 - y) <= 10.0 and abs(ax / 1000 - x) <= 10.0
    lon, lat = to_ll.transform(km[:, 1] * 1000, km[:, 0] * 1000)
    expected = np.column_stack([lat, lon])
    assert np.allclose(r.coords, expected, atol=1e-9)
    # The same route given in (row, col) pixels: the same hours (69.7 h per true km, no wait).
    by_pixel = route_season(season.grid, (20, 10), (33, 80), ice_class="Arc4", v0_kn=12.0)
    assert r.cost == pytest.approx(by_pixel.cost, rel=1e-12) and 60 < r.cost < 72

    out_csv, out_geo = tmp_path / "r.csv", tmp_path / "r.geojson"
    args = ["season", str(path), "--from", "68.74,5.46", "--to", "78.87,39.31", "--vessel", "Arc4"]
    assert main([*args, "--out", str(out_csv), "--out", str(out_geo)]) == 0
    out, err = capsys.readouterr()
    assert "projected season" in err and "69.73 h" in out  # 66.45 h in grid km
    rows = list(csv.DictReader(x for x in out_csv.read_text().splitlines() if not x.startswith("#")))
    got = np.array([[float(row["lat"]), float(row["lon"])] for row in rows])
    assert np.allclose(got, expected, atol=1e-6)
    assert np.all((got[:, 0] > 68) & (got[:, 0] < 80) & (got[:, 1] > 5) & (got[:, 1] < 40))
    feature = json.loads(out_geo.read_text())
    line = np.array(feature["geometry"]["coordinates"], float)[:, ::-1]
    assert np.allclose(line, expected, atol=1e-9)
    assert feature["properties"]["requested_start"] == list(START)
    assert feature["properties"]["ice_class"] == "Arc4"

    # seaway replan reads the GeoJSON's degrees and times: the ship's position at --at is the
    # line's, linear in time between its vertices (worked here from the file).
    at = np.datetime64("2016-02-02T12:00", "s")
    times = np.array([np.datetime64(t.rstrip("Z"), "s") for t in feature["properties"]["vertex_times"]])
    i = int(np.searchsorted(times, at, side="right") - 1)
    f = float((at - times[i]) / (times[i + 1] - times[i]))
    here = line[i] + f * (line[i + 1] - line[i])
    again = tmp_path / "r2.csv"
    code = main(
        ["replan", str(out_geo), "--forecast", str(path), "--at", "2016-02-02T12:00", "--out", str(again)]
    )
    out, err = capsys.readouterr()
    assert code == 0, err
    assert f"the ship is at {here[0]:.4f},{here[1]:.4f} (after vertex {i + 1} of {len(line)})" in out
    assert f"re-planning to {line[-1, 0]:.4f},{line[-1, 1]:.4f}" in out
    assert "the route's ice class Arc4" in out  # not the default Arc7
    replanned = list(csv.DictReader(x for x in again.read_text().splitlines() if not x.startswith("#")))
    first = (float(replanned[0]["lat"]), float(replanned[0]["lon"]))
    # the centre of the forecast grid's 20-km pixel holding it: within half its diagonal
    off_km = pyproj.Geod(ellps="WGS84").inv(first[1], first[0], here[1], here[0])[2] / 1e3
    assert off_km <= 10 * np.sqrt(2)
