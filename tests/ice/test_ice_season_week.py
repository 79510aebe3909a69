"""A week of daily SIGRID-3 charts written with pyogrio (issue 10, part 3): route times of Arc4
and Arc7 for two departures, derived by hand from the charts; a NetCDF season; the season as a
model of a prepared chart; and inputs refused with the fix."""

import numpy as np
import pytest

import seaway
from seaway.ice.seasongrid import SeasonGrid, read_season
from seaway.icenav.season import route_season
from seaway.models import IceSeasonTime
from support.reference import haversine

pyogrio_raw = pytest.importorskip("pyogrio.raw")
shapely = pytest.importorskip("shapely")

KN = 1.852
DAYS = [f"2026-07-{d:02d}" for d in range(1, 8)]


def write_chart(path, plug):
    """A channel at 72.1-72.2 N between two coasts (land at 72.0-72.1 and 72.2-72.3 N), from
    60 to 64 E: open water but for 5/10 thin first-year ice (87) at 61.5-62 E and, when `plug`,
    7/10 medium first-year ice (91) at 62.5-63 E."""
    zones = [
        ((60, 72.2, 64, 72.3), ("-9", None, "L")),
        ((60, 72.0, 64, 72.1), ("-9", None, "L")),
        ((60, 72.1, 61.5, 72.2), ("00", None, "W")),
        ((61.5, 72.1, 62, 72.2), ("50", "87", "I")),
        ((62, 72.1, 62.5, 72.2), ("00", None, "W")),
        ((62.5, 72.1, 63, 72.2), ("70", "91", "I") if plug else ("00", None, "W")),
        ((63, 72.1, 64, 72.2), ("00", None, "W")),
    ]
    geoms = shapely.to_wkb(np.array([shapely.box(*b) for b, _ in zones]))
    data = [np.array(v, dtype=object) for v in zip(*(f for _, f in zones))]
    pyogrio_raw.write(
        path,
        geoms,
        data,
        ["CT", "SA", "POLY_TYPE"],
        crs="EPSG:4326",
        geometry_type="Polygon",
        driver="ESRI Shapefile",
    )


@pytest.fixture(scope="module")
def week(tmp_path_factory):
    """Seven daily charts: the plug of medium first-year ice breaks up on 4 July."""
    from seaway.ice.grids import latlon_grid

    d = tmp_path_factory.mktemp("week")
    charts = []
    for i, day in enumerate(DAYS):
        path = d / f"aari_{day}.shp"
        write_chart(path, plug=i < 3)
        charts.append((day, path))
    return read_season(charts, latlon_grid(72.0, 72.3, 60.0, 64.0, 0.1))


def hours_along_row(speed_kn, first, last):
    """Hours from column `first` to `last` along the channel row (lat 72.15) by 3x3 steps: each
    step costs its great-circle length x the mean of its two pixels' hours per km (the line
    integral; float32 as the engine reads them)."""
    h = (1 / (np.asarray(speed_kn, float) * KN)).astype(np.float32).astype(float)
    r = float(haversine(72.15, 60.05, 72.15, 60.15))
    return sum(r * (h[c] + h[c + 1]) / 2 for c in range(first, last))


def speeds(v_open, v_thin, v_plug):
    v = np.full(40, float(v_open))
    v[15:20] = v_thin  # 61.5-62 E
    v[25:30] = v_plug  # 62.5-63 E
    return v


def test_a_week_of_daily_sigrid3_charts_arc4_and_arc7_on_two_departures(week):
    assert week.sizes == {"time": 7, "lat": 3, "lon": 40}
    assert float(week.CT[0, 1, 27]) == 7 and np.isnan(week.CT[3, 1, 27]) == False  # noqa: E712
    grid = SeasonGrid(week)
    chart = seaway.prepare(grid, neighbourhood=3)  # one prepared chart for both classes and departures
    a, b = (72.15, 60.05), (72.15, 63.95)
    run = {
        (cls, day): chart.route(
            a, b, model=IceSeasonTime(grid, cls, 14, departure=day, stage_thickness="upper")
        )
        for cls in ("Arc4", "Arc7")
        for day in ("2026-07-01", "2026-07-05")
    }
    # Paper 002 at 14 kn, the upper end of each stage's range: Arc7 (h_pass 1.4 m) makes 14 x (1 - 0.7/1.4) = 7 kn in the thin ice
    # and 14 x (1 - 1.2/1.4) = 2 kn through the plug; crawling through it (about 4.6 h) beats
    # waiting for it to break up (3 days).
    arc7 = run["Arc7", "2026-07-01"]
    assert arc7.cost == pytest.approx(hours_along_row(speeds(14, 7, 2), 0, 39), rel=1e-9)
    assert arc7.stats.voyage.hours_waiting == 0
    assert run["Arc7", "2026-07-05"].cost == pytest.approx(
        hours_along_row(speeds(14, 7, 14), 0, 39), rel=1e-9
    )
    # Arc4 (0.8 m, open ice to 6/10) crawls through the thin ice at 14 x (1 - 0.7/0.8) = 1.75 kn
    # and may not enter the 7/10 plug: it waits at its edge (column 24) for the chart of 4 July.
    arc4 = run["Arc4", "2026-07-01"]
    assert arc4.cost == pytest.approx(72.0 + hours_along_row(speeds(14, 1.75, 14), 24, 39), rel=1e-9)
    ((pixel, (lat, lon), since, waited),) = arc4.stats.voyage.waits
    assert pixel == (1, 24) and lon == pytest.approx(62.45)
    assert arc4.stats.voyage.ice_class == "Arc4"
    assert arc4.stats.voyage.hours_waiting == pytest.approx(waited, rel=1e-12)
    assert waited == pytest.approx(72.0 - hours_along_row(speeds(14, 1.75, 14), 0, 24), rel=1e-9)
    assert str(arc4.stats.voyage.arrival)[:13] == "2026-07-04T01"
    assert [str(t)[:10] for t in arc4.stats.voyage.charts_used] == ["2026-07-01", "2026-07-04"]
    late4 = run["Arc4", "2026-07-05"]
    assert late4.cost == pytest.approx(hours_along_row(speeds(14, 1.75, 14), 0, 39), rel=1e-9)
    # Smoothed through the charts: its wait kept where it was, left when the route left it, and
    # along the row's great circles (shorter than the parallel) no later.
    smooth = arc4.smoothed()
    ((pixel_s, _, since_s, waited_s),) = smooth.stats.voyage.waits
    assert pixel_s == (1, 24) and since_s <= since and waited_s >= waited
    assert smooth.cost < arc4.cost and smooth.stats.voyage.hours == smooth.cost
    assert len(smooth.pixels) < len(arc4.pixels) and smooth.stats.smoothing.waits_added == 0
    # FIFO: the later departure never arrives earlier (hours: Arc4 74.0 and 9.7, Arc7 9.7, 5.8).
    for cls in ("Arc4", "Arc7"):
        assert run[cls, "2026-07-05"].stats.voyage.arrival > run[cls, "2026-07-01"].stats.voyage.arrival


def test_a_netcdf_season_routes_as_the_dataset(week, tmp_path):
    path = tmp_path / "week.nc"
    week.drop_vars([v for v in week.data_vars if week[v].dtype == bool]).assign(
        land=week.land.astype("u1")
    ).to_netcdf(path)
    a, b = (72.15, 60.05), (72.15, 63.95)
    from_file = route_season(str(path), a, b, ice_class="Arc4", v0_kn=14, neighbourhood=3)
    in_memory = route_season(week, a, b, ice_class="Arc4", v0_kn=14, neighbourhood=3)
    assert from_file.cost == in_memory.cost and np.array_equal(from_file.pixels, in_memory.pixels)


def test_inputs_refused_with_the_fix(week, tmp_path):
    grid = SeasonGrid(week)
    model = IceSeasonTime(grid, "Arc7", 14)
    other = seaway.prepare(np.ones((3, 41)))
    with pytest.raises(
        ValueError,
        match=r"season's charts have \(3, 40\) pixels but the chart "
        r"\(3, 41\): route on the season's grid \(seaway.icenav.season.SeasonGrid.prepare\)",
    ):
        other.route((1, 0), (1, 39), model=model)
    with pytest.raises(ValueError, match=r"land has \(3, 41\) pixels but the season's charts \(3, 40\)"):
        SeasonGrid(week, land=np.zeros((3, 41), bool))
    with pytest.raises(
        ValueError,
        match=r"2026-07-02T00:00:00 is followed by 2026-07-01T00:00:00: "
        r"sorted\(charts\)",
    ):
        read_season([("2026-07-02", "b.shp"), ("2026-07-01", "a.shp")], None)
    with pytest.raises(ValueError, match=r"chart dates must be dates"):
        read_season([("first of July", "a.shp")], None)
    with pytest.raises(ValueError, match=r"ds.sortby\('time'\)"):
        SeasonGrid(week.isel(time=[0, 2, 1]))
    with pytest.raises(ValueError, match=r"outside the season \(2026-07-01T00:00:00 to 2026-07-08"):
        IceSeasonTime(grid, "Arc7", 14, departure="2026-07-08T06")
    with pytest.raises(ValueError, match=r"departure must be a date such as '2026-07-01T12'"):
        IceSeasonTime(grid, "Arc7", 14, departure="next Tuesday")
    with pytest.raises(ValueError, match="may go nowhere in any chart"):
        IceSeasonTime(grid, "Arc4", 14, speed={55: 0.0, 87: 0.0, 91: 0.0})
    with pytest.raises(
        ValueError,
        match=r"start pixel \(1, 27\) at lat 72.1500, lon 62.7500 is in "
        r"ice class Arc4 may not enter in any chart from 2026-07-01T00:00:00 on",
    ):
        closed = week.copy()
        closed["CT"] = closed.CT.where(~((closed.lon > 62.5) & (closed.lon < 63)), 10.0)
        route_season(closed, (72.15, 62.75), (72.15, 63.95), ice_class="Arc4", v0_kn=14)


@pytest.mark.cli
def test_command_line_routes_through_dated_sigrid3_files(week, tmp_path, capsys):
    from seaway.cli import main

    for i, day in enumerate(DAYS):
        write_chart(tmp_path / f"c{i}.shp", plug=i < 3)
    charts = [f"{day}=" + str(tmp_path / f"c{i}.shp") for i, day in enumerate(DAYS)]
    out = tmp_path / "arc4.geojson"
    argv = [
        "season",
        *charts,
        "--grid",
        "72,72.3,60,64,0.1",
        "--from",
        "72.15,60.05",
        "--to",
        "72.15,63.95",
        "--vessel",
        "Arc4",
        "--speed",
        "14",
        "--neighbourhood",
        "3",
        "-q",
        "--out",
        str(out),
    ]
    assert main(argv) == 0
    text = capsys.readouterr().out
    api = route_season(week, (72.15, 60.05), (72.15, 63.95), ice_class="Arc4", v0_kn=14, neighbourhood=3)
    assert f"{api.cost:.2f} h" in text and "wait " in text and "at 72.1500, 62.4500 from 2026-07-01" in text
    assert out.exists()
    # Bad command lines name the fix and exit 1.
    # Without --grid, the grid is chosen as `seaway route` chooses it (clipped to the charts) and said.
    assert main(["season", *charts, "--from", "72.15,60.05", "--to", "72.15,63.95", "-q"]) == 0
    err = capsys.readouterr().err
    assert "seaway season: grid: lat 72.00..72.30, lon 59.99..64.01" in err and "--grid" in err
    # A chart that does not cover an end is named: its extent, not the ice, stops the voyage.
    assert (
        main(
            [
                "season",
                *charts,
                "--grid",
                "72,72.3,60,66,0.1",
                "--from",
                "72.15,60.05",
                "--to",
                "72.15,65.5",
                "-q",
            ]
        )
        == 1
    )
    err = capsys.readouterr().err
    assert f"the chart of {DAYS[0]} ({tmp_path / 'c0.shp'}) does not cover the end 72.15,65.5" in err
    assert (
        main(
            [
                "season",
                charts[1],
                charts[0],
                "--grid",
                "72,72.3,60,64,0.1",
                "--from",
                "72.15,60.05",
                "--to",
                "72.15,63.95",
                "-q",
            ]
        )
        == 1
    )
    assert "is followed by 2026-07-01T00:00:00: sorted(charts)" in capsys.readouterr().err
