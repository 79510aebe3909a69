"""POLARIS (IMO MSC.1/Circ.1519): the RIV table, RIO on hand-made egg codes, operation levels,
speed limits, the cost raster and a route summary."""

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway.ice import polaris
from seaway.ice.polaris import rio_egg
from seaway.icenav import summary

# MSC.1/Circ.1519 Table 1.3, transcribed as printed (columns IF, new, grey, GW, TFY1, TFY2,
# MFY<1m, MFY, ThFY, SY, LMY, HMY).
PRINTED = """
PC1 3 3 3 3 2 2 2 2 2 2 1 1
PC2 3 3 3 3 2 2 2 2 2 1 1 0
PC3 3 3 3 3 2 2 2 2 2 1 0 -1
PC4 3 3 3 3 2 2 2 2 1 0 -1 -2
PC5 3 3 3 3 2 2 1 1 0 -1 -2 -2
PC6 3 2 2 2 2 1 1 0 -1 -2 -3 -3
PC7 3 2 2 2 1 1 0 -1 -2 -3 -3 -3
IA_Super 3 2 2 2 2 1 0 -1 -2 -3 -4 -4
IA 3 2 2 2 1 0 -1 -2 -3 -4 -5 -5
IB 3 2 2 1 0 -1 -2 -3 -4 -5 -6 -6
IC 3 2 1 0 -1 -2 -3 -4 -5 -6 -7 -8
NIS 3 1 0 -1 -2 -3 -4 -5 -6 -7 -8 -8
"""


def test_riv_table_as_printed():
    rows = [line.split() for line in PRINTED.strip().splitlines()]
    names = {"IA_Super": "IA Super", "NIS": "not ice strengthened"}
    assert {names.get(r[0], r[0]): tuple(map(int, r[1:])) for r in rows} == polaris.RIV
    assert polaris.riv_row("PC5")["ThFY"] == 0 and polaris.riv_row("IC")["HMY"] == -8
    assert polaris.riv_row("Arc7") == polaris.riv_row("PC4")  # assumed equivalence


@pytest.mark.parametrize(
    "ice_class, ct, pairs, expected",
    [
        ("PC5", 9, [(5, 93), (4, 91)], 1 * 3 + 5 * 0 + 4 * 1),  # thick FY 0, medium FY 1
        ("PC7", 10, [(10, 93)], -20),
        ("PC7", 6, [(6, 93)], 4 * 3 - 12),  # exactly 0: normal
        ("PC7", 7, [(7, 93)], 3 * 3 - 14),
        ("IA", 10, [(5, 85), (5, 88)], 5 * 2 + 5 * 1),  # grey-white 2, TFY 1st stage 1
        ("IA", 8, [(8, 91)], 2 * 3 - 16),
        ("not ice strengthened", 2, [(2, 81)], 8 * 3 + 2 * 1),  # new ice 1
        ("PC1", 10, [(10, 97)], 10),  # multi-year -> heavy MY, RIV 1
        ("PC3", 9, [(3, 96), (6, 93)], 3 + 3 * 1 + 6 * 2),  # second-year 1, thick FY 2
        ("PC4", 9, [(9, 99)], 3 - 18),  # unknown stage -> HMY (-2): conservative
        ("PC6", 9, [(3, 93)], 3 - 3 - 6),  # 6/10 unaccounted for -> the thickest stage, SA
        ("Arc7", 10, [(10, 93)], 10),  # Arc7 -> PC4 (assumed): ThFY 1
        ("IA Super", 10, [(4, 83), (6, 87)], 4 * 2 + 6 * 1),  # young -> GW, thin FY -> TFY2
    ],
)
def test_rio_on_egg_codes(ice_class, ct, pairs, expected):
    assert rio_egg(ice_class, ct, *pairs) == expected


def test_unknowns_are_conservative_and_changeable():
    assert rio_egg("PC4", 9, (9, 99), unknown_column="MFY") == 3 + 18
    assert rio_egg("PC6", np.nan, (np.nan, 87)) == 10 * 1  # CT unknown -> 10/10 of TFY2 (1)
    assert rio_egg("PC6", np.nan, (np.nan, 87), unknown_concentration=5) == 5 * 3 + 5 * 1


def test_operation_levels_and_speed_limits():
    r = np.array([5.0, 0.0, -1.0, -10.0, -10.5])
    assert polaris.operation_level(r, "PC3").tolist() == [0, 0, 1, 1, 2]
    assert polaris.operation_level(r, "IA Super").tolist() == [0, 0, 2, 2, 2]  # below PC7
    assert polaris.operation_level(r, "Arc5").tolist() == [0, 0, 1, 1, 2]  # Arc5 -> PC6
    assert [polaris.speed_limit_kn(c) for c in ("PC1", "PC2", "PC3", "PC5", "PC6", "PC7")] == [
        11,
        8,
        5,
        5,
        3,
        3,
    ]
    assert polaris.speed_limit_kn("IA") == np.inf


def _tongue_chart():
    """5 km planar chart: open water with a tongue of 10/10 thick first-year ice (93)."""
    shape = (40, 60)
    ct = np.zeros(shape)
    sa = np.full(shape, np.nan)
    ct[0:34, 29:31], sa[0:34, 29:31] = 10, 93
    dims = ("y", "x")
    return xr.Dataset(
        {
            "CT": (dims, ct),
            "CA": (dims, np.where(ct > 0, ct, np.nan)),
            "SA": (dims, sa),
            "land": (dims, np.zeros(shape, bool)),
        },
        coords={"y": np.arange(shape[0])[::-1] * 5.0, "x": np.arange(shape[1]) * 5.0},
    )


def test_polaris_cost_raster_and_routes():
    ds = _tongue_chart()
    pc4 = polaris.polaris_chart(ds, "PC4", v0_kn=10)  # ThFY RIV 1: RIO 10, normal
    pc6 = polaris.polaris_chart(ds, "PC6", v0_kn=10)  # ThFY -1: RIO -10, elevated, 3 kn
    pc7 = polaris.polaris_chart(ds, "PC7", v0_kn=10)  # ThFY -2: RIO -20, special
    assert (pc4.rio.values[5, 29], pc6.rio.values[5, 29], pc7.rio.values[5, 29]) == (10, -10, -20)
    assert (pc4.level.values[5, 29], pc6.level.values[5, 29], pc7.level.values[5, 29]) == (0, 1, 2)
    water = 1 / (10 * 1.852)
    assert pc4.cost.values[5, 0] == pytest.approx(water) and pc4.rio.values[5, 0] == 30
    assert pc6.speed_kn.values[5, 29] == 3 and pc6.cost.values[5, 29] == pytest.approx(2 / (3 * 1.852))
    assert pc7.cost.values[5, 29] == np.inf and pc7.speed_kn.values[5, 29] == 0
    a, b = (5, 5), (5, 54)  # (row, col): the chart is planar, y/x in km
    r4 = seaway.route(pc4.cost, a, b, neighbourhood=5)
    r7 = seaway.route(pc7.cost, a, b, neighbourhood=5)
    assert r4.length == pytest.approx(49 * 5) and r4.cost == pytest.approx(245 * water)
    assert r7.pixels[:, 0].max() >= 34 and r7.length > 300  # round the tip
    s4 = summary.summarize(r4, ds, time_cost=pc4.cost, polaris=pc4)
    s7 = summary.summarize(r7, ds, time_cost=pc7.cost, polaris=pc7)
    assert s4["rio_min"] == 10 and s4["rio_max"] == 30 and not s4["elevated_risk"]
    assert s4["by_stage"]["thick first-year ice"]["distance"] == pytest.approx(
        10.0
    )  # column 30: halves of two 10-km steps
    assert s4["by_concentration"]["very close 9-10/10"]["distance"] == pytest.approx(10.0)
    assert s4["length"] == pytest.approx(245) and s4["time"] == pytest.approx(r4.cost)
    assert s7["rio_min"] == 30 and not s7["special_consideration"]
    assert set(s7["by_stage"]) == {"ice free"} and s7["time"] == pytest.approx(r7.cost)
    # The elevated-risk class crosses when the detour costs more than the penalised crossing.
    r6 = seaway.route(pc6.cost, a, b, neighbourhood=5)
    s6 = summary.summarize(r6, ds, time_cost=pc6.cost, polaris=pc6)
    assert s6["elevated_risk"] and s6["rio_min"] == -10 and s6["elevated_distance"] > 0
    assert s6["time"] == pytest.approx(r6.cost)
