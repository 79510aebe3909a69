"""A season's ends and why no route gets through it (seaway.icenav.seasonwhy, route_season): an end
on land moves only as far as the limit, an end in ice that opens later stays and the route waits,
and a strait closed by first-year ice in every chart is explained by the ice, not the land."""

import functools

import numpy as np
import pytest

import seaway
from seaway.engine.snap import SnapError
from seaway.errors import NoRouteError
from seaway.ice.seasongrid import SeasonGrid
from seaway.icenav.season import route_season
from seaway.icenav.seasonwhy import snap_season_ends
from seaway.models import IceSeasonTime
from support.reference import haversine
from support.seasons import channel_season

#: The engine's steps: these tests hold them to brute force and to values by hand.
route_season = functools.partial(route_season, smooth=False)

KN = 1.852
WEST, EAST = (70.5, 60.5), (70.5, 65.5)
#: Medium first-year ice (WMO 91, 0.7-1.2 m) at 8/10 across the channel at 63.0-63.5 E on every
#: chart: over Arc4-Arc6's 6/10 and thicker than Arc4's and Arc5's h_pass; Arc7 may enter it.
STRAIT = [(d, (70.4, 70.6, 63.0, 63.5), 8.0, 91.0) for d in range(3)]
#: More ice on the first and last charts (thick first-year along the north shore): the second
#: chart is the most open one.
PATCHES = [(0, (70.56, 70.6, 61.0, 61.5), 10.0, 93.0), (2, (70.58, 70.6, 61.0, 61.2), 10.0, 93.0)]


def test_an_end_on_land_moves_to_the_nearest_water_within_the_limit():
    ds = channel_season([])
    r = route_season(ds, WEST, (70.645, 62.0), ice_class="Arc4", v0_kn=14, snap_km=20)
    # The nearest water pixel centre is 70.60 N 62.0 E (the channel's north row), 5.0 km south.
    assert tuple(r.coords[-1]) == pytest.approx((70.6, 62.0))
    km = haversine(70.645, 62.0, 70.6, 62.0)
    assert km == pytest.approx(5.004, abs=1e-3)
    assert r.requested == ((70.5, 60.5), (70.645, 62.0))
    assert r.notes == (
        f"end 70.645,62 is on an impassable pixel (land): moved {km:.1f} km to 70.6000,62.0000",
    )
    # 50 km inland: refused, naming the distance and the limit; max_km=0 only reports.
    with pytest.raises(
        SnapError,
        match=r"end 71.05,62 is on an impassable pixel \(land\); the nearest point "
        r"the ship may use is 70.6000,62.0000, 50.0 km away: farther than max_km=20",
    ):
        route_season(ds, WEST, (71.05, 62.0), ice_class="Arc4", v0_kn=14, snap_km=20)
    model = IceSeasonTime(SeasonGrid(ds), "Arc4", 14)
    with pytest.raises(SnapError) as info:
        snap_season_ends(model, WEST, (70.645, 62.0), max_km=0)
    assert info.value.moves[0].distance == pytest.approx(km)
    # Without snap_km an end on land is refused as before, naming the nearest water.
    with pytest.raises(
        ValueError,
        match=r"end is on an impassable pixel \(land, NaN or infinite cost\): "
        r"pixel \(28, 40\) at lat 70.6400, lon 62.0000; the nearest passable pixel is pixel "
        r"\(30, 40\) at lat 70.6000",
    ):
        route_season(ds, WEST, (70.645, 62.0), ice_class="Arc4", v0_kn=14)


def test_an_end_in_ice_that_opens_later_stays_and_the_route_waits():
    # Thick first-year ice 10/10 over the end on the first two charts, open water on the third.
    plug = [(d, (70.4, 70.6, 63.0, 63.5), 10.0, 93.0) for d in range(2)]
    ds = channel_season(plug)
    end = (70.5, 63.25)
    assert snap_season_ends(IceSeasonTime(SeasonGrid(ds), "Arc4", 14), WEST, end).moves == ()
    r = route_season(ds, WEST, end, ice_class="Arc4", v0_kn=14, snap_km=20)
    assert r.notes == () and tuple(r.coords[-1]) == pytest.approx(end)
    (wait,) = r.stats.voyage.waits
    # The ship waits at the last open pixel west of the ice (62.95 E) until the third chart (48 h).
    assert wait.position == pytest.approx((70.5, 62.95))
    since_h = (wait.since - np.datetime64("2026-07-01T00")) / np.timedelta64(1, "h")
    assert since_h + wait.hours == pytest.approx(48.0, abs=1e-6)
    # It got there along 70.5 N in open water at 14 kn: the great-circle steps of the route.
    k = int(np.flatnonzero(np.isclose(r.coords[:, 1], 62.95))[0])
    steps = [haversine(*p, *q) for p, q in zip(r.coords[:k], r.coords[1 : k + 1])]
    assert np.all(np.isclose(r.coords[: k + 1, 0], 70.5))
    assert since_h == pytest.approx(sum(steps) / (14 * KN), rel=1e-6)
    assert r.cost == pytest.approx(48.0 + haversine(70.5, 62.95, 70.5, 63.25) / (14 * KN), rel=1e-5)


def test_a_strait_closed_by_first_year_ice_in_every_chart_is_explained_by_the_ice():
    ds = channel_season(STRAIT + PATCHES)
    with pytest.raises(NoRouteError) as info:
        route_season(ds, WEST, EAST, ice_class="Arc4", v0_kn=14)
    err = info.value
    text = str(err)
    assert "land mask" not in text and err.cause == "ice"
    assert text.startswith(
        "no route for an Arc4 ship from 70.5,60.5 to 70.5,65.5 through the season "
        "(charts of 2026-07-01T00:00 to 2026-07-03T00:00, waiting allowed): ice closes "
        "the way in the season's most open chart for Arc4, that of 2026-07-02T00:00"
    )
    ((ice, km),) = err.closing_ice
    assert ice == "medium first-year ice (SA 91) at 8/10 (Arc7 and stronger may enter)"
    # The way crosses the strait's eleven pixel columns, 62.975-63.525 E, within the channel.
    assert haversine(70.6, 62.975, 70.6, 63.525) <= km <= haversine(70.4, 62.975, 70.4, 63.525)
    assert err.weakest_class == "Arc7" and "the weakest class that gets through the season is Arc7" in text
    # The ship gets as far as the strait's west edge (62.95 E).
    assert err.reachable[1] == pytest.approx(62.95)
    assert err.reachable_km == pytest.approx(haversine(*err.reachable, *EAST), rel=1e-9)
    # Arc7 does get through (at Andreeva 2021's speed in 1.2 m ice: 14 x (1 - 1.2 / 1.4) = 2 kn).
    r = route_season(ds, WEST, EAST, ice_class="Arc7", v0_kn=14, stage_thickness="upper")
    assert r.stats.voyage.hours_waiting == 0.0
    # Along 70.5 N: its great-circle steps at 14 kn, and 2 kn over the strait's 0.55 deg.
    assert np.all(np.isclose(r.coords[:, 0], 70.5))
    length = sum(haversine(*p, *q) for p, q in zip(r.coords[:-1], r.coords[1:]))
    w = haversine(70.5, 62.975, 70.5, 63.525)
    assert r.cost == pytest.approx(length / (14 * KN) + w * (1 / (2 * KN) - 1 / (14 * KN)), rel=1e-5)


def test_only_land_parting_the_ends_names_the_land_mask():
    ds = channel_season(STRAIT, wall=63.0)  # a land wall at 63.0 E
    with pytest.raises(NoRouteError, match="separate water bodies even with all ice open") as info:
        route_season(ds, WEST, EAST, ice_class="Arc4", v0_kn=14)
    assert info.value.cause == "land" and "check the land mask" in str(info.value)


@pytest.mark.needs_data("ocean_model", "metno_ROMS_Arctic20_1to5Feb_2016.nc")
def test_real_ocean_model_season_ends_and_a_way_closed_by_ice(shared_data):
    """MET Norway's ROMS Arctic-20km daily ice (1-5 Feb 2016; aice, hice; a planar 20-km grid:
    points are (row, col), distances in its km)."""
    import xarray as xr

    from seaway.ice.seasongrid import as_season

    with xr.open_dataset(shared_data / "ocean_model" / "metno_ROMS_Arctic20_1to5Feb_2016.nc") as src:
        ds = src[["aice", "hice", "mask"]].load()
    grid = SeasonGrid(as_season(ds.assign(land=ds["mask"] == 0).drop_vars(["latitude", "longitude"])))
    start = (20, 0)  # open water in the south-west
    model = IceSeasonTime(grid, "Arc4", 12)
    # The coastal land pixel (37, 90): the nearest pixel some chart opens, (37, 88) 40 km away,
    # lies in a pocket the ship cannot reach from the start; the nearest joined one is (33, 88).
    field = np.asarray(seaway.prepare(grid).cost_field(start, model=model))
    assert grid.dry[37, 90] and not grid.dry[37, 88] and not np.isfinite(field[37, 88])
    far = 20 * np.hypot(4, 2)
    with pytest.raises(
        SnapError,
        match=rf"end 37,90 is on an impassable pixel \(land\); the nearest point "
        rf"the ship may use is 33.0000,88.0000, {far:.1f} chart units away: farther than max_km=20",
    ):
        snap_season_ends(model, start, (37, 90))
    snapped = snap_season_ends(model, start, (37, 90), max_km=100)
    assert snapped.end == (33, 88) and snapped.moves[0].distance == pytest.approx(far)
    # (36, 66), open to Arc4 on some chart, lies behind ice over Arc4-Arc6's 6/10 in every chart.
    with pytest.raises(NoRouteError) as info:
        route_season(grid, start, (36, 66), ice_class="Arc4", v0_kn=12)
    err = info.value
    assert err.cause == "ice" and "land mask" not in str(err) and err.weakest_class == "Arc7"
    assert "that of 2016-02-05T12:00" in str(err)  # the most open chart: the last
    assert (
        err.closing_ice[0][0].startswith("ice 0.2 m thick at 6.")
        and "(Arc7 and stronger" in err.closing_ice[0][0]
    )
    assert np.isfinite(route_season(grid, start, (36, 66), ice_class="Arc7", v0_kn=12).cost)
    with pytest.raises(NoRouteError):
        route_season(grid, start, (36, 66), ice_class="Arc6", v0_kn=12)


@pytest.mark.needs_data("ocean_model", "metno_ROMS_Arctic20_1to5Feb_2016.nc")
def test_an_ocean_models_own_land_mask_is_the_seasons_land(shared_data):
    """The ROMS file's `mask` (area_type; option_0 land) closes its 363 land pixels, said in
    every route's notes, and an end there is refused as land (not as unknown ice)."""
    import xarray as xr

    path = shared_data / "ocean_model" / "metno_ROMS_Arctic20_1to5Feb_2016.nc"
    with xr.open_dataset(path) as src:
        mask = src["mask"].values
    season = seaway.open_season(str(path))
    assert np.array_equal(season.grid.dry, mask == 0) and int(season.grid.dry.sum()) == 363
    said = "the file's latitude/longitude lie up to 17.8 km (0.89 pixel) from where its grid mapping puts"
    assert any(n.startswith(said) for n in season.notes)  # the ends use the grid mapping: said
    start, land = season.plane.to_user((20, 2)), season.plane.to_user((37, 90))  # pixel centres
    assert mask[37, 90] == 0 and season.pixel(land) == (37, 90)
    with pytest.raises(SnapError, match=r"is on an impassable pixel \(land\)"):
        season.route(start, land, vessel="Arc7")
    r = season.route(start, season.plane.to_user((30, 40)), vessel="Arc7")
    assert "land: the file's mask (0 is land, 1 water)" in r.stats.voyage.assumptions
