"""Why no route (seaway.icenav.noroute, seaway.engine.reach): the ice that closes the way, the weakest
class that gets through, how far the ship gets; "check the land mask" only when the land alone
parts the ends. On a synthetic SIGRID-3 chart of the AARI winter shape (a sea of fast ice of
unknown stage between two coasts), on the real NSIDC G02202 and CIS charts, and on the real
GSHHG coastline. Expected values from outside the code under test: 4-connected bodies of usable
pixels (scipy.ndimage.label), distances by pyproj's Geod on the engine's sphere, widths of the
fast ice from the polygons' coordinates."""

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway.cli import main
from seaway.engine.reach import explain_no_route as explain_chart

pytest.importorskip("pyogrio")
shapely = pytest.importorskip("shapely")
ndimage = pytest.importorskip("scipy.ndimage")
pyproj = pytest.importorskip("pyproj")
from seaway.ice import chart_impact  # noqa: E402
from seaway.ice.grids import latlon_grid  # noqa: E402
from seaway.ice.sigrid import read_sigrid3  # noqa: E402
from seaway.icenav.noroute import explain_no_route  # noqa: E402
from support.sigrid import write_fast_channel  # noqa: E402

GEOD = pyproj.Geod(a=6371008.8, b=6371008.8)
NSIDC = ("sea_ice_concentration", "seaice_conc_daily_nh_20211231_f17_v04r00.nc")
GSHHG = ("land", "gshhg_f_landmask_1arcmin_60N.nc")
START, END = (72.05, 61.55), (72.05, 78.55)


@pytest.fixture(scope="module")
def fast_sea(tmp_path_factory):
    """AARI's winter shape (support.sigrid.write_fast_channel), its fast ice in two polygons."""
    path = write_fast_channel(tmp_path_factory.mktemp("fast") / "fast_sea.shp", fast_cuts=(70,))
    return str(path), read_sigrid3(str(path), latlon_grid(70, 75, 60, 80, 0.1))


def reachable_reference(usable, lat, lon, start, end):
    """(point, km to the end) of the usable pixel nearest the end, 4-connected to the start."""
    labels, _ = ndimage.label(usable)
    r, c = int(np.abs(lat - start[0]).argmin()), int(np.abs(lon - start[1]).argmin())
    rr, cc = np.nonzero(labels == labels[r, c])
    d = GEOD.inv(np.full(rr.size, end[1]), np.full(rr.size, end[0]), lon[cc], lat[rr])[2] / 1000
    i = int(np.argmin(d))
    return (float(lat[rr[i]]), float(lon[cc[i]])), float(d[i])


def test_fast_ice_closes_the_sea_to_arc5_and_arc7_gets_through(fast_sea):
    _, ds = fast_sea
    with pytest.raises(seaway.NoRouteError) as e:
        seaway.route(chart_impact(ds, "Arc5"), START, END, land=ds.land)
    assert "check the land mask" not in str(e.value)  # ice, not land, parts them
    err = explain_no_route(ds, "Arc5", START, END)
    assert err.cause == "ice" and err.weakest_class == "Arc7"
    ((kind, km),) = err.closing_ice
    # no first-year stage on the grid: the fast ice is assumed thick first-year (93), which
    # Grinyak et al.'s Table 3 closes to Arc5 and Table 2 opens to Arc7
    assert (
        kind
        == "fast ice of unknown stage, assumed thick first-year ice (SA 93) at 10/10 (Arc7 and stronger may enter)"
    )
    # the way crosses it where it is narrowest: 63-77 E along the northern row of pixels
    north = float(ds.lat.values[ds.lat.values < 74].max())
    assert km == pytest.approx(GEOD.inv(63, north, 77, north)[2] / 1000, rel=0.02)
    usable = np.isfinite(chart_impact(ds, "Arc5").values) & ~ds.land.values
    point, dist = reachable_reference(usable, ds.lat.values, ds.lon.values, START, END)
    assert err.reachable == pytest.approx(point) and err.reachable_km == pytest.approx(dist, abs=0.01)
    assert point[1] < 63  # the edge of the fast ice
    assert str(err) == (
        f"no route for an Arc5 ship from 72.05,61.55 to 72.05,78.55: ice closes the "
        f"way: {kind}: {km:.0f} km; the weakest class that gets through is Arc7; the "
        f"ship can get as far as {point[0]:.4f},{point[1]:.4f}, {dist:.1f} km from the end"
    )


def test_fast_ice_closed_by_the_rule_closes_it_to_every_class(fast_sea, capsys):
    path, ds = fast_sea
    err = explain_no_route(ds, "Arc7", START, END, fast_ice="closed")
    assert err.cause == "ice" and err.weakest_class is None
    assert (
        err.closing_ice[0][0]
        == "fast ice of unknown stage, closed by the fast_ice rule at 10/10 (no class may enter)"
    )
    code = main(
        [
            "route",
            path,
            "--from",
            "72.05,61.55",
            "--to",
            "72.05,78.55",
            "--grid",
            "70,75,60,80,0.1",
            "--fast-ice",
            "closed",
            "-q",
        ]
    )
    err_text = capsys.readouterr().err
    assert code == 1 and "check the land mask" not in err_text
    assert (
        "ice closes the way: fast ice of unknown stage, closed by the fast_ice rule at 10/10 (no "
        "class may enter)"
    ) in err_text
    assert "no class of seaway.ice.classes (up to Arc9 and the icebreakers) gets through" in err_text
    assert f"the ship can get as far as {err.reachable[0]:.4f},{err.reachable[1]:.4f}" in err_text


def test_land_that_parts_the_ends_is_named_as_the_land(fast_sea, tmp_path):
    _, ds = fast_sea
    walled = ds.copy()
    walled["land"] = ds.land | ((ds.lon > 69.9) & (ds.lon < 70.1))  # a land bridge at 70 E
    err = explain_no_route(walled, "Arc9", START, END)
    assert err.cause == "land" and err.closing_ice == () and err.weakest_class is None
    assert "the ends lie in separate water bodies even with all ice open" in str(err)
    assert "check the land mask" in str(err)


@pytest.mark.needs_data(*NSIDC)
def test_nsidc_december_closes_the_northern_sea_route_to_arc5(shared_data, capsys):
    """NSIDC G02202, 31 December 2021: from the Barents Sea to the Bering Sea. Every pixel of
    15 % ice or more is taken as thick first-year ice (93, assumed), which Arc5 may not enter;
    Arc7 may. The reachable point is checked against the 4-connected open water of the Barents
    Sea, and its distance by Geod."""
    from seaway import open_chart

    path = str(shared_data.joinpath(*NSIDC))
    code = main(["route", path, "--vessel", "Arc5", "--from", "71.25,50.95", "--to", "60,-175", "-q"])
    err = capsys.readouterr().err
    assert code == 1 and "check the land mask" not in err
    assert (
        "error: no route for an Arc5 ship from 71.25,50.95 to 60,-175: ice closes the way: thick "
        "first-year ice (SA 93, assumed) at 2-10/10 (Arc8 and stronger may enter):"
    ) in err
    # Arc7 may enter the ice (Grinyak et al. 2022) but has no speed of its own in 1.6 m
    # (Andreeva 2021: it passes 1.4 m): Arc8 is the weakest that gets through on its own
    assert "the weakest class that gets through is Arc8" in err
    data = open_chart(path, vessel="Arc5")
    usable = np.isfinite(data.cost.values) & ~data.land.values
    y, x = data.cost.y.values, data.cost.x.values
    labels, _ = ndimage.label(usable)
    sy, sx = data.projection.to_xy_km(71.25, 50.95)
    rr, cc = np.nonzero(labels == labels[np.abs(y - sy).argmin(), np.abs(x - sx).argmin()])
    ll = data.projection.to_latlon(y[rr], x[cc])
    d = GEOD.inv(np.full(rr.size, -175.0), np.full(rr.size, 60.0), ll[:, 1], ll[:, 0])[2] / 1000
    i = int(np.argmin(d))
    assert f"the ship can get as far as {ll[i, 0]:.4f},{ll[i, 1]:.4f}, {d[i]:.1f} km from the end" in err


@pytest.mark.needs_data(*GSHHG)
def test_real_coastline_land_or_cost(shared_data):
    """GSHHG's coastline at 66-74 N, 60-80 E: Baydaratskaya Bay and the Gulf of Ob meet only north
    of the Yamal peninsula (73.5 N). Cut at 71 N the chart parts them by land: said so; with the
    sea north of Yamal closed by a cost of inf instead, the cost closes the way, not the land."""
    land = xr.open_dataset(shared_data.joinpath(*GSHHG))["land"].sel(lat=slice(66, 74), lon=slice(60, 80))
    land = land.load().astype(bool)
    land.attrs = {}  # its flag_meanings would make the ones below "land" flags
    bay, ob = (69.15, 66.5), (68.15, 73.75)
    cut = land.sel(lat=slice(66, 71))
    err = explain_chart(xr.ones_like(cut, dtype=float), bay, ob, land=cut)
    assert err.cause == "land" and "check the land mask" in str(err)
    cost = xr.ones_like(land, dtype=float).where(~((land.lat > 72) & (land.lat < 72.3)), np.inf)
    seaway.route(xr.ones_like(land, dtype=float), bay, ob, land=land)  # open: round Yamal
    with pytest.raises(seaway.NoRouteError) as e:
        seaway.route(cost, bay, ob, land=land)
    assert "check the land mask" not in str(e.value)
    err = explain_chart(cost, bay, ob, land=land)
    assert err.cause == "impassable" and "check the land mask" not in str(err)
    usable = np.isfinite(cost.values) & ~land.values
    point, dist = reachable_reference(usable, land.lat.values, land.lon.values, bay, ob)
    assert err.reachable == pytest.approx(point) and err.reachable_km == pytest.approx(dist, abs=0.01)


@pytest.mark.slow
def test_kara_size_chart_explains_arc4_quickly_enough():
    """The built-in 1900 x 2300 Kara chart: Arc4 between two bodies of water it may use is closed
    by medium first-year ice (Arc6 may enter) and first-year ice (Arc7); checked against the
    4-connected bodies. (Takes about 1.5 s here; no wall-clock assertion.)"""
    from seaway.samples import ice_impact, kara_sea

    ds = kara_sea()
    usable = np.isfinite(ice_impact(ds.stage_of_development, "Arc4").values) & ~ds.land.values
    labels, n = ndimage.label(usable)
    sizes = ndimage.sum(usable, labels, range(1, n + 1))
    a, b = np.argsort(-sizes)[:2] + 1
    pts = []
    for k in (a, b):
        rr, cc = np.nonzero(labels == k)
        pts.append((float(ds.lat[rr[len(rr) // 2]]), float(ds.lon[cc[len(rr) // 2]])))
    err = explain_no_route(ds, "Arc4", pts[0], pts[1])
    assert err.cause == "ice" and err.weakest_class == "Arc7"
    kinds = [k for k, _ in err.closing_ice]
    assert any(
        k.startswith("first-year ice (WMO 86)") and k.endswith("(Arc7 and stronger may enter)") for k in kinds
    )
    point, dist = reachable_reference(usable, ds.lat.values, ds.lon.values, pts[0], pts[1])
    assert err.reachable == pytest.approx(point) and err.reachable_km == pytest.approx(dist, abs=0.01)
