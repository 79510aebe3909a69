"""route_many on the `kara` sample with real port coordinates (issue 30): ports that lie a pixel
or two inland at the chart's resolution fail without snap_km and route with it; every move is
the great-circle distance to the nearest usable pixel centre, a move beyond the limit is refused
with SnapError's message, and each failing row names its cause."""

import numpy as np
import pytest

import seaway
from seaway.ice import ice_impact
from seaway.samples import kara_sea

pd = pytest.importorskip("pandas")

PORTS = {
    "Murmansk": (68.97, 33.08),  # west of the chart (50-110 E)
    "Varandey": (68.82, 58.07),
    "Sabetta": (71.27, 72.07),
    "Dikson": (73.51, 80.55),
    "Kara Gate": (70.43, 57.9),
    "Vilkitsky": (77.9, 104.0),
}
PAIRS = {
    "gate-sabetta": ("Kara Gate", "Sabetta"),
    "varandey-dikson": ("Varandey", "Dikson"),
    "murmansk-sabetta": ("Murmansk", "Sabetta"),
}
VOYAGES = {k: (PORTS[a], PORTS[b]) for k, (a, b) in PAIRS.items()}


def impact(cls):
    return lambda ds: ice_impact(ds.stage_of_development, cls)


@pytest.fixture(scope="module")
def kara():
    return kara_sea()  # 1900 x 2300 pixels, 0.4-1.1 km


def arc_km(a, b):
    """Great-circle km between (lat, lon) points: the angle between their unit vectors."""
    (p1, l1), (p2, l2) = np.radians(a), np.radians(b)
    u = np.array([np.cos(p1) * np.cos(l1), np.cos(p1) * np.sin(l1), np.sin(p1)])
    v = np.array([np.cos(p2) * np.cos(l2), np.cos(p2) * np.sin(l2), np.sin(p2)])
    return 6371.0088 * np.arctan2(np.linalg.norm(np.cross(u, v)), u @ v)


def nearest_usable(ds, cost, point):
    """The usable pixel centre nearest `point`, by brute force over the whole chart."""
    ok = np.isfinite(cost.values) & ~ds.land.values
    lat, lon = np.meshgrid(ds.lat.values, ds.lon.values, indexing="ij")
    la, lo = lat[ok], lon[ok]
    near = np.argsort((la - point[0]) ** 2 + ((lo - point[1]) * np.cos(np.radians(point[0]))) ** 2)[:50]
    km = [arc_km(point, (la[i], lo[i])) for i in near]
    i = near[int(np.argmin(km))]
    return (la[i], lo[i]), min(km)


@pytest.mark.slow
def test_real_ports_snap_as_single_routes_do(kara):
    vessels = {"Arc7": impact("Arc7"), "PC6": impact("PC6")}
    before = seaway.route_many(kara, VOYAGES, vessels=vessels, threads=2)
    assert before.status.tolist() == ["bad input"] * 6
    assert before.cause.tolist() == ["land", "land", "off chart"] * 2
    table = seaway.route_many(kara, VOYAGES, vessels=vessels, threads=2, snap_km=20)
    arc7, pc6 = table[table.vessel == "Arc7"], table[table.vessel == "PC6"]
    assert arc7.status.tolist() == ["ok", "ok", "bad input"]
    assert arc7.cause.tolist() == ["", "", "off chart"] and "outside the chart" in arc7.error.iloc[2]
    cost = impact("Arc7")(kara)
    moved = []
    for row in arc7.iloc[:2].itertuples():
        for name in ("start", "end"):
            asked = (getattr(row, f"{name}_lat"), getattr(row, f"{name}_lon"))
            used = (getattr(row, f"used_{name}_lat"), getattr(row, f"used_{name}_lon"))
            km = getattr(row, f"{name}_moved_km")
            assert asked == PORTS[PAIRS[row.voyage][name == "end"]]
            if asked == PORTS["Kara Gate"]:  # at sea: not moved
                assert used == asked and km == 0.0
                continue
            pixel, nearest = nearest_usable(kara, cost, asked)
            assert used == pytest.approx(pixel, abs=1e-9)
            assert km == pytest.approx(arc_km(asked, used), rel=1e-9)
            assert km == pytest.approx(nearest, rel=1e-9)
            assert (
                f"{name} {asked[0]:g},{asked[1]:g} is on an impassable pixel (land): moved {km:.1f} km"
                in row.notes
            )
            moved.append(round(km, 2))
    assert moved == [1.4, 1.34, 1.43]  # Sabetta; Varandey, Dikson: inland by 1.3-1.4 km
    first = arc7.iloc[0]
    used = (first.used_start_lat, first.used_start_lon), (first.used_end_lat, first.used_end_lon)
    single = seaway.route(cost, *used, land=kara.land)
    assert arc7.cost.iloc[0] == single.cost and arc7.length.iloc[0] == single.length
    # PC6 may not enter the ice off Sabetta: its nearest usable water is 225 km away
    assert pc6.status.tolist() == ["bad input"] * 3 and pc6.cause.tolist() == ["land", "land", "off chart"]
    assert "225.1 km away: farther than max_km=20" in pc6.error.iloc[0]
    assert pc6.used_end_lat.isna().all() and pc6.end_moved_km.isna().all()


def test_an_end_closed_by_ice_is_not_land(kara):
    table = seaway.route_many(
        kara,
        {"gate-vilkitsky": (PORTS["Kara Gate"], PORTS["Vilkitsky"])},
        vessels={"Arc7": impact("Arc7"), "PC6": impact("PC6")},
        threads=1,
        method="astar",
        weight=3,
    )
    assert table.status.tolist() == ["ok", "bad input"]
    assert table.cause.tolist() == ["", "closed by ice"]
