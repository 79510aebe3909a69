"""Fast ice in a season of ice charts (seaway.ice.seasonfast): SIGRID-3 charts written to disk in
AARI's winter shape (fast ice of unknown stage: FA 08, SA 99, CT 92) keep their form of ice, and
each chart follows the static path's rule (seaway.ice.forms): a season of identical charts routes
exactly as the static chart does, "closed" is explained as fast ice, and the assumption is said
once, naming the charts and pixels. The same on the real CIS chart (fast ice with its stage,
bergy water)."""

import functools
import json

import numpy as np
import pytest

import seaway
from seaway._core import haversine_km
from seaway.errors import NoRouteError
from seaway.ice import andreeva
from seaway.ice.seasongrid import SeasonGrid, read_season
from seaway.ice.speed import ice_speed
from seaway.icenav.season import route_season
from seaway.icenav.seasonwhy import closed_reason
from seaway.models import IceSeasonTime

pytest.importorskip("pyogrio")
shapely = pytest.importorskip("shapely")
pytest.importorskip("rasterio")
from seaway.ice.grids import latlon_grid  # noqa: E402
from seaway.ice.sigrid import read_sigrid3  # noqa: E402
from support.sigrid import write_chart  # noqa: E402

#: The engine's steps: these tests hold them to brute force and to values by hand.
route_season = functools.partial(route_season, smooth=False)

KN = 1.852
GRID = (70, 75, 60, 80, 0.1)  # 50 x 200 pixels, pixel edges on the polygons' edges
START, END = (72.5, 61.0), (72.5, 79.0)
DAYS = ("2026-01-01", "2026-01-02", "2026-01-03")
FAST = {"POLY_TYPE": "I", "CT": "92", "SA": "99", "FA": "08"}  # AARI: fast ice, stage unknown
CIS = ("ice_charts_sigrid3", "cis_eastern_arctic", "cis_SGRDREA_20201102T.gpkg")
HOW = "(set it with fast_ice= (API) or --fast-ice (CLI): closed, a WMO stage code, or nearby)"
NEARBY = "the thickest first-year stage the chart shows nearby (on the grid)"


def _chart(path, pack_stage):
    """A channel at 71-74 N between two shores (land 70-71 and 74-75 N): open water at 60-62 E
    and 78-80 E, pack ice of `pack_stage` at 5/10 (FA 04 floes) at 62-63 E, fast ice of unknown
    stage at 63-77 E (three polygons, 140 x 30 = 4200 pixels), bergy water at 77-78 E (CT 02, SA
    98, FA 10, as CIS codes it)."""
    box = shapely.box
    rows = [
        (box(60, 70, 80, 71), {"POLY_TYPE": "L"}),
        (box(60, 74, 80, 75), {"POLY_TYPE": "L"}),
        (box(60, 71, 62, 74), {"POLY_TYPE": "W", "CT": "00"}),
        (box(78, 71, 80, 74), {"POLY_TYPE": "W", "CT": "00"}),
        (box(62, 71, 63, 74), {"POLY_TYPE": "I", "CT": "50", "SA": pack_stage, "FA": "04"}),
        (box(63, 71, 68, 74), FAST),
        (box(68, 71, 72, 74), FAST),
        (box(72, 71, 77, 74), FAST),
        (box(77, 71, 78, 74), {"POLY_TYPE": "I", "CT": "02", "SA": "98", "FA": "10"}),
    ]
    return str(write_chart(path, rows))


@pytest.fixture(scope="module")
def charts(tmp_path_factory):
    """Two AARI-shaped charts: pack ice thin first-year (87) on one, medium first-year (91) on
    the other."""
    folder = tmp_path_factory.mktemp("aari_season")
    return _chart(folder / "aari_87.shp", "87"), _chart(folder / "aari_91.shp", "91")


@pytest.fixture(scope="module")
def same(charts):
    """Three daily charts, all the same (pack 87)."""
    return read_season({d: charts[0] for d in DAYS}, latlon_grid(*GRID))


def _sentence(days, said, pixels=4200):
    each = [f"{d} ({pixels} pixels)" for d in days]
    where = (
        f"the chart of {each[0]}"
        if len(each) == 1
        else f"the charts of {', '.join(each[:-1])} and {each[-1]}"
    )
    return f"in {where}: ASSUMED {said}"


def test_the_season_keeps_the_form_of_ice_and_each_chart_takes_the_rule(charts, same):
    assert {"FA", "FB", "FC", "SB", "SC", "free_water"} <= set(same.data_vars)
    assert int((same.FA.values[0] == 8).sum()) == 4200 and set(
        np.unique(same.SA.values[0][same.FA.values[0] == 8])
    ) == {99.0}
    mixed = read_season({DAYS[0]: charts[0], DAYS[1]: charts[1]}, latlon_grid(*GRID))
    model = IceSeasonTime(mixed, "Arc7", 12, concentration_limit=False, stage_thickness="upper")
    # "nearby", chart by chart: thin first-year (87, to 0.7 m) beside the first chart's fast ice,
    # medium first-year (91, to 1.2 m) beside the second's; Andreeva: V = (1 - h / 1.4 m) x 12 kn.
    at = (25, 100)  # 72.55 N, 70.05 E: fast ice
    for k, h in enumerate((0.7, 1.2)):
        v = (1 - h / 1.4) * 12
        assert model.hours_per_km[k][at] == np.float32(1 / (v * KN))
    bergy = (25, 175)  # 77.55 E: bergy water (SA 98 glacier ice on the chart) costs as open water
    assert model.hours_per_km[0][bergy] == np.float32(1 / (12 * KN))
    assert model.fast_ice == "nearby"
    assert model.assumptions == (
        "fast ice of unknown stage (FA 08, SA 99) "
        + _sentence(DAYS[:1], f"thin first-year ice (WMO 87), {NEARBY}")
        + "; "
        + _sentence(DAYS[1:2], f"medium first-year ice (WMO 91), {NEARBY}")
        + f" {HOW}",
        "open or bergy water (CT 01/02) in the charts of 2026-01-01 (bergy water on 300 pixels) and "
        "2026-01-02 (bergy water on 300 pixels): freely navigable water (WMO-No. 259), costed as ice "
        "free; icebergs may be present",
    )
    # A stage code as the rule: medium first-year (91) in both charts.
    chosen = IceSeasonTime(mixed, "Arc7", 12, fast_ice=91, concentration_limit=False, stage_thickness="upper")
    assert chosen.hours_per_km[0][at] == chosen.hours_per_km[1][at] == np.float32(7 / (12 * KN))
    assert "ASSUMED medium first-year ice (WMO 91), as you chose" in chosen.assumptions[0]
    with pytest.raises(ValueError, match="fast_ice must be 'nearby', 'closed' or a WMO stage code"):
        IceSeasonTime(mixed, "Arc7", 12, fast_ice="thick")


def test_a_season_of_identical_charts_routes_as_the_static_chart(charts, same):
    r = route_season(
        same, START, END, ice_class="Arc7", v0_kn=12, concentration_limit=False, stage_thickness="upper"
    )
    # The static integral route through the same chart with the same rule (seaway.ice.speed, the
    # hours per km as the season's engine reads them: float32).
    ds = read_sigrid3(charts[0], latlon_grid(*GRID))
    v = ice_speed(ds, "Arc7", 12, fast_ice="nearby", stage_thickness="upper")
    hours = andreeva.time_cost(v / 12, 12).astype(np.float32).astype(float)
    static = seaway.route(hours, START, END, land=ds.land, edge_cost="integral", method="astar")
    assert r.cost == pytest.approx(static.cost, rel=1e-9)
    assert np.array_equal(r.pixels, static.pixels) and r.stats.voyage.hours_waiting == 0
    # By hand: 12 kn in open and bergy water, 6 kn (f2 = 1 - 0.7 / 1.4) in the pack and the
    # fast ice (62-77 E), integrated densely along the route's steps.
    total, c = 0.0, r.coords
    for a, b in zip(c[:-1], c[1:]):
        lon = a[1] + (np.arange(1000) + 0.5) / 1000 * (b[1] - a[1])
        per_km = np.where((lon > 62) & (lon < 77), 1 / (6 * KN), 1 / (12 * KN))
        total += haversine_km(*a, *b) * per_km.mean()
    assert r.cost == pytest.approx(total, rel=1e-6) and r.cost == pytest.approx(49.36, abs=0.01)
    # Along the parallel of 72.5 N it would take 15 deg (500.3 km) at 6 kn + 3 deg at 12 kn.
    deg = haversine_km(72.5, 70.0, 72.5, 71.0)
    assert r.cost < deg * (15 / (6 * KN) + 3 / (12 * KN)) == pytest.approx(49.65, abs=0.01)
    assert r.assumptions[0] == (
        "fast ice of unknown stage (FA 08, SA 99) "
        + _sentence(DAYS, f"thin first-year ice (WMO 87), {NEARBY}")
        + f" {HOW}"
    )
    assert r.assumptions == r.stats.voyage.assumptions


def test_fast_ice_closed_by_the_rule_is_named_in_the_no_route_and_the_snap(charts, same):
    with pytest.raises(NoRouteError) as info:
        route_season(same, START, END, ice_class="Arc7", fast_ice="closed", concentration_limit=False)
    err = info.value
    assert err.cause == "ice" and err.weakest_class is None
    ((name, km),) = err.closing_ice
    assert name == "fast ice of unknown stage, closed by the fast_ice rule at 10/10 (no class may enter)"
    # 14 degrees of longitude (63-77 E) between 71 and 74 N
    assert 14 * 111.2 * np.cos(np.radians(74)) < km < 14 * 111.4 * np.cos(np.radians(71))
    assert "no class up to Arc9 gets through the season" in str(err) and err.reachable[1] < 63
    # The rule recorded by read_season holds when the route gives none.
    recorded = read_season({d: charts[0] for d in DAYS[:2]}, latlon_grid(*GRID), fast_ice="closed")
    with pytest.raises(NoRouteError, match="closed by the fast_ice rule"):
        route_season(recorded, START, END, ice_class="Arc7", concentration_limit=False)
    # An end in the fast ice: the reason a snap gives, and the refusal without a snap.
    model = IceSeasonTime(same, "Arc7", 12, fast_ice="closed", concentration_limit=False)
    assert closed_reason(model)(25, 100) == (
        "ice an Arc7 ship may not enter in any chart from 2026-01-01T00:00:00 on; at departure "
        "fast ice of unknown stage, closed by the fast_ice rule at 10/10"
    )
    with pytest.raises(
        ValueError, match=r"\(last chart: fast ice of unknown stage, closed by the fast_ice rule at 10/10\)"
    ):
        seaway.prepare(SeasonGrid(same)).route((72.55, 70.05), END, model=model)


def test_the_concentration_limit_keeps_arc7_out_of_fast_ice_and_names_it(same):
    # Fast ice is 10/10: over Arc7's 8/10 (Grinyak et al. 2022 Table 1) under the season's
    # default concentration limit, whatever its assumed stage; Arc9 (10/10) gets through.
    with pytest.raises(NoRouteError) as info:
        route_season(same, START, END, ice_class="Arc7")
    ((name, _),) = info.value.closing_ice
    assert name == (
        "fast ice of unknown stage, assumed thin first-year ice (SA 87) at 10/10 (Arc9 and stronger may enter)"
    )
    assert info.value.weakest_class == "Arc9"


@pytest.mark.cli
def test_cli_season_fast_ice_switch_says_the_assumption_once(charts, tmp_path, capsys):
    from seaway.cli import main

    dated = [f"{d}={charts[0]}" for d in DAYS]  # the voyage (49.4 h) within the charts' validity
    ends = ["--from", "72.5,61", "--to", "72.5,79", "--grid", "70,75,60,80,0.1", "-q"]
    out = tmp_path / "r.geojson"
    assert main(["season", *dated, *ends, "--no-concentration-limit", "--out", str(out)]) == 0
    said = (
        "fast ice of unknown stage (FA 08, SA 99) "
        + _sentence(DAYS, f"thin first-year ice (WMO 87), {NEARBY}")
        + f" {HOW}"
    )
    stdout, err = capsys.readouterr()
    assert err.count(f"seaway season: assumed: {said}\n") == 1 and err.count("fast ice") == 1
    assert f"assumed: {said}" in stdout  # the route's own table
    assert said in json.loads(out.read_text())["properties"]["assumptions"]
    assert main(["season", *dated, *ends, "--no-concentration-limit", "--fast-ice", "closed"]) == 1
    err = capsys.readouterr().err
    assert "ASSUMED closed to every class" in err
    assert "ice closes the way in the season's most open chart for Arc7" in err
    assert "fast ice of unknown stage, closed by the fast_ice rule at 10/10 (no class may enter)" in err
    with pytest.raises(SystemExit):
        main(["season", *dated, *ends, "--fast-ice", "thick"])
    assert "fast_ice must be 'nearby', 'closed' or a WMO stage code" in capsys.readouterr().err


@pytest.mark.needs_data(*CIS)
def test_real_cis_chart_as_a_season_keeps_fast_ice_stages_and_bergy_water(shared_data):
    path = str(shared_data.joinpath(*CIS))
    grid = latlon_grid(62, 84, -113, -22, (0.1, 0.25))
    season = read_season({"2020-11-02": path, "2020-11-09": path}, grid)  # weekly charts
    ds = read_sigrid3(path, grid)
    fast = ds.FA.values == 8
    assert (season.FA.values == 8).sum() == 2 * fast.sum() and fast.sum() > 1000
    model = IceSeasonTime(season, "Arc7", 12, concentration_limit=False)
    # The chart gives every fast-ice polygon its stage: nothing assumed about fast ice; its
    # bergy water (CT 02, SA 98) is ice free, said once for both charts.
    (said,) = model.assumptions
    n = f"open water on {(ds.free_water.values == 1).sum()} pixels and bergy water on {(ds.free_water.values == 2).sum()} pixels"
    assert said.startswith(
        f"open or bergy water (CT 01/02) in the charts of 2020-11-02 ({n}) and 2020-11-09 ({n}): "
    )
    assert (model.hours_per_km[0][ds.free_water.values == 2] == np.float32(1 / (12 * KN))).all()
    # Fast multi-year ice (SA 97) closes to Arc7, and the reason names it as fast ice.
    r, c = np.argwhere(fast & (ds.SA.values == 97))[0]
    assert closed_reason(model)(r, c) == (
        "ice an Arc7 ship may not enter in any chart from 2020-11-02T00:00:00 on; at departure "
        "fast ice, multi-year ice (SA 97) at 10/10"
    )
    # Davis Strait -> Baffin Bay: the season of one chart twice is the static integral route.
    route = route_season(season, (64, -57), (75, -70), ice_class="Arc7", concentration_limit=False)
    hours = andreeva.time_cost(ice_speed(ds, "Arc7", 12) / 12, 12).astype(np.float32).astype(float)
    static = seaway.route(hours, (64, -57), (75, -70), land=SeasonGrid(season).dry, edge_cost="integral")
    assert route.cost == pytest.approx(static.cost, rel=1e-9) and route.assumptions == (said,)


def test_a_bad_fast_ice_rule_is_refused_before_the_charts_are_read(tmp_path):
    # The files do not exist: the rule is checked first, so the message is about the rule.
    missing = {d: str(tmp_path / f"{d}.shp") for d in DAYS}
    with pytest.raises(
        ValueError, match=r"fast_ice must be 'nearby', 'closed' or a WMO stage code .* got 'thick'"
    ):
        read_season(missing, latlon_grid(*GRID), fast_ice="thick")
