"""The best departure in a window (OpenSeason.best_departure, OpenForecast.best_departure): the
departure that arrives first (the latest of those that do), or by a deadline with the least fuel;
on a channel closed by ice for three days, and through a forecast of currents."""

from __future__ import annotations

import numpy as np
import pytest

import seaway
from seaway.errors import NoRouteError
from seaway.vessel import load
from support.forecasts import forecast
from support.seasons import channel_season

WEST, EAST = (70.5, 60.1), (70.5, 65.9)


def closed_three_days(tmp_path):
    """A channel of open water plugged by 10/10 medium first-year ice at 62.5-63 E on the charts
    of 1-3 July (Arc4 may not enter it), open from 4 July."""
    plug = [(d, (70.4, 70.6, 62.5, 63.0), 10.0, 91.0) for d in range(3)]
    path = tmp_path / "channel.nc"
    channel_season(plug, days=6).to_netcdf(path)
    return seaway.open_season(str(path))


def test_the_latest_departure_that_still_arrives_first(tmp_path):
    season = closed_three_days(tmp_path)
    choice = season.best_departure(
        WEST, EAST, ("2026-07-01", "2026-07-05"), step_h=12, vessel="Arc4", speed_kn=12
    )
    first = season.route(WEST, EAST, vessel="Arc4", speed_kn=12, depart="2026-07-01")
    arrival = np.datetime64(first.stats.voyage.arrival, "s")
    assert choice.best.arrival == arrival  # leaving first arrives first: the ship may wait
    # to the plug (62.5 E) is about 90 km, 4 h at 12 kn: leaving at 12:00 on 3 July still meets it
    # at its opening (midnight), leaving at midnight on 4 July does not
    assert choice.best.departure == np.datetime64("2026-07-03T12:00:00")
    later = {d.departure: d for d in choice.tried}[np.datetime64("2026-07-04T00:00:00")]
    assert later.arrival > arrival and later.waiting_h == 0
    assert choice.best.waiting_h < first.stats.voyage.hours_waiting
    assert choice.best.under_way_h == pytest.approx(first.stats.voyage.hours_under_way, rel=1e-9)
    assert "best departure in the window: 2026-07-03 12:00" in choice.route.notes[-1]
    assert "*" in choice.table().splitlines()[5] and len(choice.tried) == 9


def test_by_a_deadline_the_least_fuel(tmp_path):
    season = closed_three_days(tmp_path)
    ship = load("pc6-general-cargo")  # 13.5 kn, a fuel curve: 1.2 t/h at 13.5 kn
    choice = season.best_departure(
        WEST, EAST, ("2026-07-01", "2026-07-05"), step_h=24, vessel=ship, arrive_by="2026-07-04T12:00"
    )
    assert choice.best.arrival <= np.datetime64("2026-07-04T12:00")
    rate = float(np.interp(13.5, ship.fuel_speeds_kn, ship.fuel_rates_t_per_h))
    assert choice.best.fuel_t == pytest.approx(choice.best.under_way_h * rate, rel=1e-9)
    assert all(
        d.fuel_t >= choice.best.fuel_t - 1e-9
        for d in choice.tried
        if d.arrival is not None and d.arrival <= np.datetime64("2026-07-04T12:00")
    )
    with pytest.raises(NoRouteError, match="no departure of the window arrives by 2026-07-01T06:00:00"):
        season.best_departure(
            WEST, EAST, ("2026-07-01", "2026-07-02"), vessel=ship, arrive_by="2026-07-01T06:00"
        )


def test_through_a_forecast_leaving_first_arrives_first(tmp_path):
    """Currents only (FIFO): the earliest departure arrives first; each departure is timed."""
    ds = forecast(
        shape=(21, 41),
        frames=9,
        hours=6,
        ce=np.linspace(-1.0, 1.0, 9)[:, None, None] * np.ones((9, 21, 41)),
        cn=0.0,
    )
    ds.to_netcdf(tmp_path / "fc.nc")
    fc = seaway.open_forecast(str(tmp_path / "fc.nc"))
    choice = fc.best_departure((61.0, 0.2), (61.0, 3.8), ("2026-01-01T00", "2026-01-02T00"), step_h=6)
    assert choice.best.departure == np.datetime64("2026-01-01T00:00")
    arrivals = [d.arrival for d in choice.tried]
    assert arrivals == sorted(arrivals) and len(arrivals) == 5
    hours = [d.hours for d in choice.tried]
    assert hours[-1] < hours[0]  # the current turns with the ship: later voyages are quicker


def test_the_command_line_prints_the_departures_tried(tmp_path, capsys):
    from seaway.cli import main

    closed_three_days(tmp_path)
    args = [
        "season",
        str(tmp_path / "channel.nc"),
        "--from",
        "70.5,60.1",
        "--to",
        "70.5,65.9",
        "--vessel",
        "Arc4",
    ]
    assert main([*args, "--depart-window", "2026-07-01,2026-07-05,12", "-q"]) == 0
    out = capsys.readouterr().out
    assert "departures tried (the earliest arrival; of the departures that make it, the latest):" in out
    assert "* 2026-07-03T12:00  arrives" in out
    assert (
        main(
            [
                "route",
                str(tmp_path / "channel.nc"),
                "--from",
                "70.5,60.1",
                "--to",
                "70.5,65.9",
                "--depart-window",
                "2026-07-01,2026-07-02",
            ]
        )
        == 1
    )
    assert "--depart-window need --forecast FILE" in capsys.readouterr().err
