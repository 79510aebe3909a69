"""`seaway route --forecast`: weather routing from the command line on forecast files written
the way real ones are (CDO's ECMWF waves, CF one variable per file, GRIB through cfgrib), the
roles, the departure refused outside the forecast or held with --persist, the vessel files, the
objectives, and ice and weather in one voyage; each against the API on the same forecast."""

from __future__ import annotations

import json

import numpy as np
import pytest
import xarray as xr

from seaway.cli import main
from seaway.icenav.season import route_season
from seaway.vessel import load
from seaway.weather import Vessel, decode_time, read_forecasts, route_ice_weather, route_time
from seaway.weather.forecast import find_fields
from support import forecast_files as ff
from support.seasons import retreating_edge

pytestmark = pytest.mark.cli
A, B = "--from=70.5,21", "--to=73.5,29"
SHIP = Vessel(speed_kn=12.0, displacement_t=15000.0)
CDO_ROLES = [
    "--forecast-variable",
    "wave_height=var229",
    "--forecast-variable",
    "wave_from=var230",
    "--forecast-variable",
    "wave_period=var232",
]


def _run(capsys, *argv):
    code = main(["route", *map(str, argv), "-q"])
    out, err = capsys.readouterr()
    return code, out, err


def _land(ds):
    from global_land_mask import globe

    la, lo = np.meshgrid(ds.lat.values, ds.lon.values, indexing="ij")
    return globe.is_land(la, lo)


def test_cdo_waves_are_refused_naming_the_flags_then_routed_as_the_same_forecast(tmp_path, capsys):
    path = ff.write_cdo_waves(tmp_path / "waves.nc")
    raw = xr.open_dataset(path)  # a new user's first try: the time axis stays undecoded floats
    assert raw.time.dtype == np.float64
    code, _, err = _run(capsys, "--forecast", path, A, B)
    assert code == 1 and "--forecast-variable wave_height=var229 --forecast-variable wave_from=var230" in err
    out_geo = tmp_path / "r.geojson"
    code, out, err = _run(
        capsys, "--forecast", path, *CDO_ROLES, "--depart", "2026-10-01T06:00", A, B, "--out", out_geo
    )
    assert code == 0, err
    twin = route_time(
        ff.in_memory(("hs", "wdir", "per")),
        (70.5, 21),
        (73.5, 29),
        vessel=SHIP,
        departure="2026-10-01T06:00",
        land=_land(ff.in_memory()),
    )
    props = json.loads(out_geo.read_text())["properties"]
    assert props["time_h"] == pytest.approx(twin.cost, rel=1e-12) and props["cost"] == props["time_h"]
    assert (
        props["departure"] == "2026-10-01T06:00:00Z"
        and props["arrival"] == str(twin.stats.voyage.arrival)[:19] + "Z"
    )
    assert props["forecast"] == "waves.nc (2026-10-01T00:00 to 2026-10-04T00:00, every 6 h)"
    assert "departure 2026-10-01T06:00:00Z" in out and "ETA (UTC)" in out
    # The API takes the raw file too: its time axis is decoded, the roles checked.
    api = route_time(
        raw,
        (70.5, 21),
        (73.5, 29),
        vessel=SHIP,
        departure="2026-10-01T06:00",
        land=_land(ff.in_memory()),
        variables={"wave_height": "var229", "wave_from": "var230"},
    )
    assert api.cost == pytest.approx(twin.cost, rel=1e-12)  # the period plays no part in the time


def test_a_misspelt_role_is_refused_naming_the_roles(tmp_path, capsys):
    path = ff.write_cdo_waves(tmp_path / "waves.nc")
    with pytest.raises(SystemExit) as exc:
        main(["route", "--forecast", str(path), "--forecast-variable", "wave_direction=var230", A, B])
    assert exc.value.code == 2
    assert (
        "unknown role 'wave_direction' (did you mean wave_from?); the roles are current_east, "
        in capsys.readouterr().err
    )
    with pytest.raises(
        ValueError, match=r"unknown forecast role 'wave_direction' \(did you mean wave_from\?\)"
    ):
        find_fields(decode_time(xr.open_dataset(path)), {"wave_height": "var229", "wave_direction": "var230"})


def test_departures_outside_the_forecast_are_refused_or_held_with_persist(tmp_path, capsys):
    path = ff.write_cdo_waves(tmp_path / "waves.nc")
    code, _, err = _run(capsys, "--forecast", path, *CDO_ROLES, "--depart", "2026-09-25T00:00", A, B)
    assert code == 1
    assert (
        "departure 2026-09-25T00:00 is 144 h before the forecast's first time (the forecast covers "
        "2026-10-01T00:00 to 2026-10-04T00:00)"
    ) in err and "--persist" in err
    rtz = tmp_path / "r.rtz"
    code, out, err = _run(
        capsys,
        "--forecast",
        path,
        *CDO_ROLES,
        "--depart",
        "2026-10-05T00:00",
        "--persist",
        A,
        B,
        "--out",
        rtz,
    )
    assert (
        code == 0
        and "persistence: the departure 2026-10-05T00:00 is 24 h after the forecast's last time" in err
    )
    assert "assumed: persistence" in out and 'validityPeriodStart="2026-10-05T00:00:00Z"' in rtz.read_text()


def test_one_file_per_variable_merged_on_time(tmp_path, capsys):
    paths = ff.write_cf_per_variable(tmp_path, step_h=12)  # currents twice a day
    ds, notes = read_forecasts(paths)
    assert (
        "forecast files merged on their common span 2026-10-01T00:00:00.000000000 to "
        "2026-10-04T00:00:00.000000000, every 6 h (linear in time)" in notes
    )
    assert sorted(ds.data_vars) == [
        "current_east",
        "current_north",
        "wave_from",
        "wave_height",
        "wave_period",
        "wind_east",
        "wind_north",
    ]
    # A current field every 12 h read every 6 h: the mean of its neighbours (linear in time).
    full = ff.in_memory()
    assert np.allclose(ds.current_north.isel(time=1), full.cur_n.isel(time=[0, 2]).mean("time"))
    out_geo = tmp_path / "r.geojson"
    argv = [a for p in paths for a in ("--forecast", p)]
    code, _, err = _run(capsys, *argv, "--vessel-file", "pc6-general-cargo", A, B, "--out", out_geo)
    assert code == 0, err
    pc6 = load("pc6-general-cargo").vessel
    twin = route_time(ds, (70.5, 21), (73.5, 29), vessel=pc6, land=_land(full))
    assert json.loads(out_geo.read_text())["properties"]["time_h"] == pytest.approx(twin.cost, rel=1e-12)


def test_grib_through_cfgrib_routes_as_the_same_forecast(tmp_path, capsys):
    eccodes = pytest.importorskip("eccodes")
    pytest.importorskip("cfgrib")
    path = ff.write_grib(tmp_path / "gale.grib2", eccodes)
    ds, notes = read_forecasts([path])
    assert "forecast wave_height = " + str(path) + ":swh (GRIB short name swh)" in notes
    full = ff.in_memory()
    assert ds.time.values.tolist() == full.time.values.tolist()  # valid times, not lead times
    assert np.abs(ds.wave_height.values - full.hs.values).max() < 1e-3  # GRIB packing
    out_geo = tmp_path / "r.geojson"
    code, _, err = _run(capsys, "--forecast", path, A, B, "--out", out_geo)
    assert code == 0, err
    twin = route_time(
        full[["hs", "wdir", "per", "wind_e", "wind_n"]], (70.5, 21), (73.5, 29), vessel=SHIP, land=_land(full)
    )
    assert json.loads(out_geo.read_text())["properties"]["time_h"] == pytest.approx(twin.cost, rel=1e-4)


def test_an_undecodable_time_axis_is_refused_naming_the_variable(tmp_path, capsys):
    ds = ff.in_memory(("hs",)).assign_coords(time=("time", np.arange(ff.FRAMES) * 6.0, {"units": "hours"}))
    ds.to_netcdf(tmp_path / "bad.nc")
    code, _, err = _run(capsys, "--forecast", tmp_path / "bad.nc", A, B)
    assert code == 1 and "cannot decode its time variable 'time' (units 'hours'): give it CF units" in err


def test_least_fuel_that_arrives_in_time_and_the_options_need_a_forecast(tmp_path, capsys):
    paths = ff.write_cf_per_variable(tmp_path)
    argv = [a for p in paths for a in ("--forecast", p)]
    code, out, err = _run(
        capsys,
        *argv,
        "--vessel-file",
        "pc6-general-cargo",
        "--objective",
        "fuel",
        "--arrive-by",
        "2026-10-02T00:00",
        A,
        B,
    )
    assert code == 0, err
    hours = float(out.split("fuel ")[-1].split(" t over ")[1].split(" h")[0])
    assert hours <= 24.0 + 0.05  # arrives by the deadline (printed to 0.1 h)
    code, _, err = _run(capsys, "kara", "--persist", A, B)
    assert code == 1 and "--persist need --forecast FILE" in err
    code, _, err = _run(capsys, "kara", "--objective", "fuel", A, B)
    assert code == 1 and "--objective fuel need --forecast FILE" in err


def test_ice_and_weather_in_one_voyage_from_the_command_line(tmp_path, capsys):
    season = retreating_edge(days=4)
    season.to_netcdf(tmp_path / "ice.nc")
    g = season.isel(time=slice(0, 3))
    fc = xr.Dataset(
        {
            "ce": (
                ("time", "lat", "lon"),
                np.full((3,) + g.CT.shape[1:], 0.2),
                {"standard_name": "eastward_sea_water_velocity"},
            ),
            "cn": (
                ("time", "lat", "lon"),
                np.full((3,) + g.CT.shape[1:], 0.3),
                {"standard_name": "northward_sea_water_velocity"},
            ),
        },
        coords={"time": g.time.values, "lat": g.lat.values, "lon": g.lon.values},
    )
    fc.to_netcdf(tmp_path / "currents.nc")
    csv = tmp_path / "r.csv"
    code, out, err = _run(
        capsys,
        tmp_path / "ice.nc",
        "--forecast",
        tmp_path / "currents.nc",
        "--vessel",
        "Arc7",
        "--from=71,70",
        "--to=76,74",
        "--out",
        csv,
    )
    assert code == 0, err
    api = route_ice_weather(
        season, fc, (71.0, 70.0), (76.0, 74.0), ice_class="Arc7", vessel=Vessel(speed_kn=12.0)
    )
    alone = route_season(season, (71.0, 70.0), (76.0, 74.0), ice_class="Arc7", v0_kn=12.0)
    assert f"voyage {api.cost // 24:.0f} d" in out and api.cost < alone.cost  # the current helps north
    assert (
        "# departure 2026-07-01T00:00:00Z, arrival " + str(api.stats.voyage.arrival)[:19] in csv.read_text()
    )


def test_replan_continues_the_voyage_from_where_the_ship_is(tmp_path, capsys):
    paths = ff.write_cf_per_variable(tmp_path)
    argv = [a for p in paths for a in ("--forecast", p)]
    first = tmp_path / "voyage.geojson"
    assert _run(capsys, *argv, A, B, "--out", first)[0] == 0
    props = json.loads(first.read_text())["properties"]
    # With the same forecast, the rest of a time-optimal route is optimal from where the ship is
    # (FIFO): re-planning at a vertex it reaches keeps the arrival (to the second of the times).
    k = len(props["vertex_times"]) // 2
    at = props["vertex_times"][k].rstrip("Z")  # to the second: the ship is at vertex k
    again = tmp_path / "again.geojson"
    code = main(["replan", str(first), *map(str, argv), "--at", at, "--out", str(again), "-q"])
    _, err = capsys.readouterr()
    assert code == 0, err
    assert f"at {at} the ship is at " in err and f"(after vertex {k + 1} of " in err
    new = json.loads(again.read_text())["properties"]
    assert new["departure"] == at + "Z"
    assert (
        abs(
            (np.datetime64(new["arrival"].rstrip("Z")) - np.datetime64(props["arrival"].rstrip("Z")))
            / np.timedelta64(1, "s")
        )
        <= 60
    )
    code = main(["replan", str(first), *map(str, argv), "--at", "2026-10-09T00:00", "-q"])
    assert code == 1 and "is outside the voyage" in capsys.readouterr().err


def test_the_least_time_in_danger_when_no_route_avoids_the_danger_zones(tmp_path, capsys):
    # A ship that avoids wind over 11 m/s (Sotnikova 2009's danger zones); by the last day the
    # gale blows up to 18 m/s over the south-west, the start among it: no safe route exists, so
    # the route spends the least hours in danger, said and recorded in the outputs.
    paths = ff.write_cf_per_variable(tmp_path)
    argv = [a for p in paths for a in ("--forecast", p)]
    ship_file = tmp_path / "ship.toml"
    ship_file.write_text(
        'name = "feeder"\nservice_speed_kn = 12.0\ndisplacement_t = 15000.0\ndanger_wind_ms = 11.0\n'
    )
    out_geo = tmp_path / "r.geojson"
    code, out, err = _run(
        capsys, *argv, "--vessel-file", ship_file, "--depart", "2026-10-03T18:00", A, B, "--out", out_geo
    )
    assert code == 0, err
    props = json.loads(out_geo.read_text())["properties"]
    api = route_time(
        ff.in_memory(),
        (70.5, 21),
        (73.5, 29),
        vessel=load(ship_file).vessel,
        departure="2026-10-03T18:00",
        land=_land(ff.in_memory()),
    )
    assert api.stats.danger is not None and props["hours_in_danger"] == pytest.approx(api.stats.danger.hours)
    assert props["hours_in_danger"] > 0 and "no route avoids the danger zones" in err
    assert "through danger zones:" in out and props["time_h"] == pytest.approx(api.cost, rel=1e-12)
