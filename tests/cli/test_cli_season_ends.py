"""`seaway season --snap [--snap-km KM]` and its answer when no route gets through the season:
on a NetCDF season of a channel between two shores (tests/support/seasons.channel_season)."""

import json

import numpy as np
import pytest

from seaway.cli import main
from support.reference import haversine
from support.seasons import channel_season

pytestmark = pytest.mark.cli

STRAIT = [(d, (70.4, 70.6, 63.0, 63.5), 8.0, 91.0) for d in range(3)]  # medium first-year 8/10


def write(ds, path):
    ds.drop_vars("land").assign(land=ds.land.astype("u1")).to_netcdf(path)
    return str(path)


def test_season_snaps_an_end_on_land_within_the_limit_and_records_it(tmp_path, capsys):
    season = write(channel_season([]), tmp_path / "open.nc")
    base = ["season", season, "--from", "70.5,60.5", "--vessel", "Arc4", "--speed", "14", "-q"]
    # Without --snap: the end on land is refused, with the point it would take.
    assert main(base + ["--to", "70.645,62"]) == 1
    km = haversine(70.645, 62.0, 70.6, 62.0)  # 5.0 km to the channel's north row
    assert (
        f"end 70.645,62 is on an impassable pixel (land); the nearest point the ship may use is "
        f"70.6000,62.0000, {km:.1f} km away: give it, or pass --snap to move the end there"
    ) in capsys.readouterr().err
    out = tmp_path / "r.geojson"
    assert main(base + ["--to", "70.645,62", "--snap", "--out", str(out)]) == 0
    moved = (
        f"end 70.645,62 is on an impassable pixel (land): moved {km:.1f} km to 70.6000,62.0000 "
        "(--snap, at most 20 km)"
    )
    assert f"seaway season: {moved}" in capsys.readouterr().err
    props = json.loads(out.read_text())["properties"]
    assert props["requested_end"] == [70.645, 62.0] and props["end"] == pytest.approx([70.6, 62.0])
    assert props["requested_start"] == props["start"] == [70.5, 60.5]
    assert moved in props["assumptions"]
    # 50 km inland: refused, naming the distance and --snap-km; --snap-km 0 never moves.
    assert main(base + ["--to", "71.05,62", "--snap"]) == 1
    far = haversine(71.05, 62.0, 70.6, 62.0)
    assert far == pytest.approx(50.04, abs=0.01)
    assert (
        f"the nearest point the ship may use is 70.6000,62.0000, {far:.1f} km away, farther than "
        f"--snap-km 20: give a point in water the ship may use, or --snap-km {np.ceil(far):.0f} to "
        "move the end there"
    ) in capsys.readouterr().err
    assert main(base + ["--to", "70.645,62", "--snap", "--snap-km", "0"]) == 1
    assert f"{km:.1f} km away, farther than --snap-km 0" in capsys.readouterr().err


def test_season_keeps_an_end_in_ice_that_opens_later_and_waits(tmp_path, capsys):
    plug = [(d, (70.4, 70.6, 63.0, 63.5), 10.0, 93.0) for d in range(2)]  # thick first-year, 2 days
    season = write(channel_season(plug), tmp_path / "plug.nc")
    out = tmp_path / "w.geojson"
    assert (
        main(
            [
                "season",
                season,
                "--from",
                "70.5,60.5",
                "--to",
                "70.5,63.25",
                "--vessel",
                "Arc4",
                "--speed",
                "14",
                "--snap",
                "-q",
                "--out",
                str(out),
            ]
        )
        == 0
    )
    text, err = capsys.readouterr()
    assert "moved" not in err
    assert "at 70.5000, 62.9500 from 2026-07-01T03:30" in text
    props = json.loads(out.read_text())["properties"]
    assert props["end"] == props["requested_end"] == [70.5, 63.25]
    assert props["hours_waiting"] == pytest.approx(48.0 - 3.5073, abs=1e-3)


def test_season_with_no_way_through_names_the_ice_and_exits_1(tmp_path, capsys):
    season = write(channel_season(STRAIT), tmp_path / "strait.nc")
    args = ["season", season, "--from", "70.5,60.5", "--to", "70.5,65.5", "--speed", "14", "-q"]
    assert main(args + ["--vessel", "Arc4"]) == 1  # as `seaway route` exits on no route
    err = capsys.readouterr().err
    assert err.startswith(
        "seaway season: error: no route for an Arc4 ship from 70.5,60.5 to 70.5,65.5 "
        "through the season (charts of 2026-07-01T00:00 to 2026-07-03T00:00, waiting "
        "allowed): ice closes the way in the season's most open chart for Arc4, that "
        "of 2026-07-03T00:00"
    )
    assert "medium first-year ice (SA 91) at 8/10 (Arc7 and stronger may enter)" in err
    assert "the weakest class that gets through the season is Arc7" in err and "land mask" not in err
    assert main(args + ["--vessel", "Arc7"]) == 0
