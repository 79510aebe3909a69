"""seaway.snap_ends: an end the ship may not use moves, at most max_km, to the nearest usable
point in water that joins both ends (never each on its own into a pocket), the requested and
used ends recorded. Expected points come from outside the code under test: the 4-connected
components of the usable pixels (scipy.ndimage.label: the engine never steps across a corner
of an impassable pixel) and great-circle distances by pyproj's Geod on the engine's sphere."""

import numpy as np
import pytest

import seaway
from seaway import export

ndimage = pytest.importorskip("scipy.ndimage")
pyproj = pytest.importorskip("pyproj")
GEOD = pyproj.Geod(a=6371008.8, b=6371008.8)
LAT, LON = np.round(np.arange(70.0, 76.001, 0.1), 6), np.round(np.arange(60.0, 80.001, 0.1), 6)


def pocket_chart():
    """The shape of the AARI winter case: thick first-year ice (impassable for the class) at
    60-61.8 E with a pocket of young ice (usable, 61 x 3 pixels cut off) at 60.9-61.1 E,
    72.9-73.1 N; open water from 61.8 E, with an island at 69.3-69.7 E, 72.8-73.2 N."""
    cost = np.full((LAT.size, LON.size), 2.0)  # open water
    cost[:, LON < 61.8] = np.inf
    cost[np.ix_((LAT >= 72.9) & (LAT <= 73.1), (LON >= 60.9) & (LON <= 61.1))] = 15.0
    land = np.zeros(cost.shape, bool)
    land[np.ix_((LAT >= 72.8) & (LAT <= 73.2), (LON >= 69.3) & (LON <= 69.7))] = True
    return cost, land


START, END = (73.0, 60.5), (73.0, 69.5)  # in the thick ice, and on the island


def reference(cost, land, ends):
    """For each 4-connected body of usable pixels: the nearest pixel to each end and the
    distances (km); returned for the body with the least total move."""
    usable = np.isfinite(cost) & ~land
    labels, n = ndimage.label(usable)
    best = None
    for k in range(1, n + 1):
        rr, cc = np.nonzero(labels == k)
        moves = []
        for p in ends:
            d = GEOD.inv(np.full(rr.size, p[1]), np.full(rr.size, p[0]), LON[cc], LAT[rr])[2] / 1000
            i = int(np.argmin(d))
            moves.append(((float(LAT[rr[i]]), float(LON[cc[i]])), float(d[i])))
        if best is None or moves[0][1] + moves[1][1] < best[0][1] + best[1][1]:
            best = moves
    return best


def test_both_ends_move_into_the_water_that_joins_them_not_into_the_pocket():
    cost, land = pocket_chart()
    (s_ref, s_km), (e_ref, e_km) = reference(cost, land, (START, END))
    assert s_ref[1] >= 61.8 and 40 < s_km < 45  # the open water, 42 km away; the pocket is 15 km
    snapped = seaway.snap_ends(cost, START, END, lat=LAT, lon=LON, land=land, max_km=50)
    assert snapped.start == pytest.approx(s_ref, abs=1e-9) and snapped.end == pytest.approx(e_ref, abs=1e-9)
    assert [m.distance for m in snapped.moves] == pytest.approx([s_km, e_km], abs=0.01)
    assert snapped.requested == (START, END)
    r = seaway.route(cost, snapped.start, snapped.end, lat=LAT, lon=LON, land=land)  # joined
    assert r.cost == pytest.approx(2 * r.length, rel=1e-9)  # open water all the way
    # each end on its own would have gone into different water: the start into the pocket
    pocket = (72.9 <= s_ref[0] <= 73.1) and (60.9 <= s_ref[1] <= 61.1)
    assert not pocket


def test_a_move_farther_than_the_limit_is_refused_naming_the_distance():
    cost, land = pocket_chart()
    (s_ref, s_km), (e_ref, e_km) = reference(cost, land, (START, END))
    with pytest.raises(seaway.SnapError) as e:
        seaway.snap_ends(cost, START, END, lat=LAT, lon=LON, land=land)  # max_km=20 by default
    (move,) = e.value.moves  # the end moves 6.5 km: allowed; the start 42 km: not
    assert move.name == "start" and move.distance == pytest.approx(s_km, abs=0.01) and e.value.limit == 20
    assert move.to == pytest.approx(s_ref) and move.why == "an impassable pixel (cost NaN or infinite)"
    assert str(e.value).startswith(
        f"start 73,60.5 is on an impassable pixel (an impassable pixel (cost "
        f"NaN or infinite)); the nearest point the ship may use is "
        f"{s_ref[0]:.4f},{s_ref[1]:.4f}, {s_km:.1f} km away: farther than "
        "max_km=20"
    )


def test_one_usable_end_keeps_its_water_and_the_other_joins_it():
    cost, land = pocket_chart()
    inside = (73.0, 61.0)  # in the pocket: usable, so it stays; the end must join the pocket
    snapped = seaway.snap_ends(cost, inside, END, lat=LAT, lon=LON, land=land, max_km=500)
    assert snapped.start == inside and [m.name for m in snapped.moves] == ["end"]
    rr, cc = np.nonzero((np.isfinite(cost) & ~land) & (cost == 15.0))
    d = GEOD.inv(np.full(rr.size, END[1]), np.full(rr.size, END[0]), LON[cc], LAT[rr])[2] / 1000
    assert snapped.moves[0].distance == pytest.approx(d.min(), abs=0.01)  # into the pocket, 272 km
    assert seaway.route(cost, snapped.start, snapped.end, lat=LAT, lon=LON, land=land).cost > 0


def test_the_route_records_the_requested_ends_in_every_output(tmp_path):
    cost, land = pocket_chart()
    snapped = seaway.snap_ends(cost, START, END, lat=LAT, lon=LON, land=land, max_km=50)
    r = snapped.record(seaway.route(cost, snapped.start, snapped.end, lat=LAT, lon=LON, land=land))
    assert r.requested == (START, END) and len(r.assumptions) == 2
    assert (
        r.assumptions[0].startswith("start 73,60.5 is on an impassable pixel")
        and "moved 42." in r.assumptions[0]
    )
    s = r.summary()
    assert s["requested_start"] == START and s["start"] == pytest.approx(snapped.start)
    props = export.geojson(r)["properties"]
    assert props["requested_end"] == [73.0, 69.5] and props["end"] == pytest.approx(list(snapped.end))
    assert "requested 73-00.00N 060-30.00E -> 73-00.00N 069-30.00E" in str(r)
    assert f"end {snapped.end[0]:.5f},{snapped.end[1]:.5f} (requested 73,69.5)" in export.gpx(r)
    assert "(requested 73,60.5)" in export.rtz(r)
    head = [x for x in export.csv_text(r).splitlines() if x.startswith("#")]
    assert head[1] == f"# start {snapped.start[0]:.5f},{snapped.start[1]:.5f} (requested 73,60.5)"
    assert head[3].startswith("# assumed: start 73,60.5 is on an impassable pixel")


def test_planar_charts_snap_in_pixels():
    cost = np.ones((20, 30))
    cost[:, 10:12] = np.inf  # a wall
    cost[5, 3] = np.inf
    snapped = seaway.snap_ends(cost, (5, 3), (5, 5), max_km=2)
    assert snapped.start in ((4, 3), (6, 3), (5, 2), (5, 4)) and snapped.moves[0].distance == 1.0
    across = seaway.snap_ends(cost, (5, 3), (5, 20), max_km=10)  # the end's water, past the wall
    assert across.start == (5, 12) and across.moves[0].distance == 9.0 and across.unit == "chart units"
    with pytest.raises(seaway.SnapError, match="start 5,10 is on an impassable pixel"):
        seaway.snap_ends(cost, (5, 10), (5, 20), max_km=0)  # report, never move
    with pytest.raises(ValueError, match="lies outside the chart"):
        seaway.snap_ends(cost, (50, 3), (5, 20))
