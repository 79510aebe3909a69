"""`seaway route --forecast` on a real projected ocean model: MET Norway's ROMS Arctic-20km
(polar stereographic, lon_0 58 E; ubar/vbar barotropic_sea_water_x/y_velocity, i.e. along the
grid's axes, not east/north), resampled onto the box around the ends with its currents rotated,
and the rotation checked at the model's own nodes against ubar/vbar turned by hand."""

from __future__ import annotations

import json

import numpy as np
import pytest
import xarray as xr

from seaway.cli import main
from seaway.weather import on_grid, read_forecasts

pytestmark = [pytest.mark.cli, pytest.mark.needs_data("ocean_model", "metno_ROMS_Arctic20_1to5Feb_2016.nc")]
ROMS = "ocean_model/metno_ROMS_Arctic20_1to5Feb_2016.nc"
ENDS = ["--depart", "2016-02-01T12:00", "--from", "70.5,20", "--to", "76,45"]
MAPPED = ["--forecast-variable", "current_east=ubar", "--forecast-variable", "current_north=vbar"]


def test_the_roms_currents_route_on_the_command_line(shared_data, tmp_path, capsys):
    path = shared_data / ROMS
    out_geo = tmp_path / "r.geojson"
    code = main(["route", "--forecast", str(path), *MAPPED, *ENDS, "--out", str(out_geo)])
    out, err = capsys.readouterr()
    assert code == 0, err
    props = json.loads(out_geo.read_text())["properties"]
    calm_h = props["length"] / (12.0 * 1.852)  # the default 12 kn over the route's own track
    # The route leans on the Norwegian Atlantic / North Cape current: quicker than calm water
    # over its own ~1000 km track, by minutes (a few cm/s), not hours.
    assert 950.0 < props["length"] < 1100.0
    assert calm_h - 1.0 < props["time_h"] < calm_h
    said = props["assumptions"]
    for line in (
        "resampled from its Polar Stereographic (variant B) grid (+proj=stere +a=6371000 +b=6371000 "
        "+lat_0=90 +lat_ts=60 +lon_0=58 +type=crs) onto the lat/lon grid (62 x 76 pixels), bilinear",
        "grid-relative vectors rotated to east/north by the angle between the grid's y axis and north",
        "% of the grid lies outside metno_ROMS_Arctic20_1to5Feb_2016.nc's model grid: no weather "
        "(calm, no current) is assumed there",
        "about the forecast's 20 km resolution",
    ):
        assert any(line in s for s in said), line
        assert line in err
    assert "ubar is grid-relative (barotropic_sea_water_x_velocity): rotated to east/north" in err
    # Without --forecast-variable the CF names find the same fields: the same voyage.
    code = main(["route", "--forecast", str(path), *ENDS, "--out", str(tmp_path / "auto.geojson"), "-q"])
    _, err = capsys.readouterr()
    assert code == 0, err
    auto = json.loads((tmp_path / "auto.geojson").read_text())["properties"]
    assert auto["time_h"] == pytest.approx(props["time_h"], rel=1e-12)
    # The 3-D current is refused, naming the surface field.
    code = main(
        [
            "route",
            "--forecast",
            str(path),
            "--forecast-variable",
            "current_east=u",
            "--forecast-variable",
            "current_north=v",
            *ENDS,
        ]
    )
    _, err = capsys.readouterr()
    assert code == 1 and "u (current_east) has a vertical axis 'depth' (17 levels)" in err
    assert "--forecast-variable current_east=ubar" in err and "broadcast" not in err


def test_roms_currents_at_its_nodes_are_ubar_vbar_turned_by_hand(shared_data):
    pyproj = pytest.importorskip("pyproj")
    path = shared_data / ROMS
    raw = xr.open_dataset(path)
    ds, _ = read_forecasts(path)
    crs = raw["polar_stereographic"].attrs["proj4_string"]
    to_ll = pyproj.Transformer.from_crs(crs, "EPSG:4326", always_xy=True)
    checked = 0
    for i, j in [(10, 20), (25, 45), (40, 70), (30, 10)]:
        u, v = (float(raw[n].isel(time=2, Y=i, X=j)) for n in ("ubar", "vbar"))
        if not (np.isfinite(u) and np.isfinite(v)):
            continue
        lon, lat = to_ll.transform(float(raw.X[j]) * 1e3, float(raw.Y[i]) * 1e3)
        # North polar stereographic: at t = lon - lon_0 east is (cos t, sin t) in grid axes and
        # north (-sin t, cos t).
        t = np.radians(lon - 58.0)
        east, north = u * np.cos(t) + v * np.sin(t), -u * np.sin(t) + v * np.cos(t)
        out, _ = on_grid(ds, [lat], [lon])
        got = [float(out[r].isel(time=2).squeeze()) for r in ("current_east", "current_north")]
        assert got == pytest.approx([east, north], abs=1e-5)
        checked += 1
    assert checked >= 3
