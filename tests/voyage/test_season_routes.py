"""OpenSeason.routes: the routes from one start to many ends through a season from one search
per start pixel used; each is what route(start, end, method="dijkstra") gives (the same
coordinates, hours, waits and notes) or the SeawayError it raises, in that end's place."""

import numpy as np
import pytest

import seaway
from seaway.fleet import route_voyages
from support.seasons import DAY0, retreating_edge

START = (71.0, 70.0)
#: Open water, medium first-year ice 8/10 beyond the edge (which no chart opens to Arc4), land
#: 9 km from water, off the chart, farther ice, and the first end again.
ENDS = [(72.0, 75.0), (76.0, 74.0), (74.0, 61.9), (60.0, 61.0), (77.6, 79.0), (72.0, 75.0)]


@pytest.fixture(scope="module")
def season(tmp_path_factory):
    path = tmp_path_factory.mktemp("routes") / "week.nc"
    retreating_edge(days=4).to_netcdf(path)
    return seaway.open_season(str(path))


def _single(season, end, **kw):
    try:
        return season.route(START, end, method="dijkstra", **kw)
    except seaway.SeawayError as exc:
        return exc


@pytest.mark.parametrize("vessel", ["Arc4", "Arc7"])
@pytest.mark.parametrize("snap_km", [None, 30.0])
def test_routes_are_the_single_dijkstra_routes(season, vessel, snap_km):
    kw = dict(vessel=vessel, depart=DAY0 + np.timedelta64(1, "D"), snap_km=snap_km)
    got = season.routes(START, ENDS, **kw)
    assert len(got) == len(ENDS)
    kinds = []
    for end, r in zip(ENDS, got):
        one = _single(season, end, **kw)
        assert type(r) is type(one)
        if isinstance(one, seaway.SeawayError):
            assert str(r) == str(one)
            kinds.append(type(one).__name__)
            continue
        np.testing.assert_array_equal(r.coords, one.coords)
        assert r.stats.voyage.hours == one.stats.voyage.hours and r.notes == one.notes
        assert r.stats.voyage.wait_h.tolist() == one.stats.voyage.wait_h.tolist()
        assert r.requested == (START, end)
        kinds.append("Route")
    arc7 = vessel == "Arc7"
    assert kinds[0] == kinds[5] == "Route" and kinds[3] == "SeawayError"  # off the chart, in its place
    assert kinds[2] == ("Route" if snap_km else "SnapError")  # on land: moved only with snap_km
    assert kinds[1] == kinds[4] == ("Route" if arc7 else "SnapError")


def test_the_default_astar_route_arrives_as_early(season):
    for end, r in zip(ENDS, season.routes(START, ENDS, vessel="Arc7", smooth=False, snap_km=30)):
        if not isinstance(r, seaway.SeawayError):
            assert r.cost == pytest.approx(
                season.route(START, end, vessel="Arc7", smooth=False, snap_km=30).cost, rel=1e-9
            )


def test_a_batch_searches_once_per_vessel_start_and_departure(season, monkeypatch):
    calls = []
    routes = type(season).routes
    monkeypatch.setattr(
        type(season),
        "routes",
        lambda self, a, ends, **k: calls.append(len(ends)) or routes(self, a, ends, **k),
    )
    voyages = {f"to {i}": (START, end) for i, end in enumerate(ENDS)} | {"back": ((76.0, 74.0), START)}
    days = [DAY0, DAY0 + np.timedelta64(1, "D")]
    table = route_voyages(season, voyages, vessels=("Arc4", "Arc7"), departures=days, snap_km=30)
    assert sorted(calls) == [1] * 4 + [6] * 4  # 2 vessels x 2 days x (one start of 6 voyages, "back")
    for row in table.itertuples():
        one = _single(
            season,
            voyages[row.voyage][1],
            vessel=row.vessel,
            depart=np.datetime64(row.departure, "s"),
            snap_km=30,
        )
        if row.voyage == "back":
            continue
        if isinstance(one, seaway.SeawayError):
            assert row.error == str(one)
        else:
            assert row.hours == one.stats.voyage.hours
