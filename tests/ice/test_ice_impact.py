"""Ice classes and paper 000's impact tables (seaway.ice.classes, seaway.ice.impact), and the
ice-tongue chart that an Arc5 ship must go around and an Arc7 ship may cross."""

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway import samples as charts
from seaway.ice import classes, impact
from seaway.ice.impact import ice_impact

INF = np.inf
# Paper 000, Tables 2 and 3, transcribed by the paper's Russian ice-type names; the codes each
# name covers are the WMO stages (thin = 87 and its stages 88, 89).
NAMES = {
    "Открытая вода": [55],
    "Начальные виды": [81],
    "Нилас": [82],
    "Серый": [84],
    "Молодой": [83],
    "Серо-белый": [85],
    "Тонкий": [87, 88, 89],
    "Однолетний": [86],
    "Средний": [91],
    "Толстый": [93],
}
TABLE_2 = {
    "Открытая вода": 2,
    "Начальные виды": 3,
    "Нилас": 5,
    "Серый": 8,
    "Молодой": 10,
    "Серо-белый": 13,
    "Тонкий": 15,
    "Однолетний": 20,
    "Средний": 25,
    "Толстый": 30,
}
TABLE_3 = {
    "Открытая вода": 1,
    "Начальные виды": 3,
    "Нилас": 5,
    "Серый": 10,
    "Молодой": 15,
    "Серо-белый": 25,
    "Тонкий": 30,
    "Однолетний": INF,
    "Средний": INF,
    "Толстый": INF,
}
# Paper 000, Table 1: class -> thickness (m) it may enter.
TABLE_1 = {
    "Ice1": 0.4,
    "Ice2": 0.5,
    "Ice3": 0.7,
    "Arc4": 0.8,
    "Arc5": 1.0,
    "Arc6": 1.3,
    "Arc7": 1.4,
    "Arc8": 2.1,
    "Arc9": 3.5,
    "Icebreaker6": 1.5,
    "Icebreaker7": 2.0,
    "Icebreaker8": 3.0,
    "Icebreaker9": 4.0,
}


def _by_code(table):
    return {code: float(table[name]) for name, codes in NAMES.items() for code in codes}


@pytest.mark.parametrize(
    "ice_class, table", [("Arc7", TABLE_2), ("Arc8", TABLE_2), ("Arc9", TABLE_2), ("Arc5", TABLE_3)]
)
def test_paper_000_tables_exactly(ice_class, table):
    expected = _by_code(table)
    assert impact.ICE_IMPACT[ice_class] == expected
    codes = np.array(sorted(expected), dtype=float)
    assert ice_impact(codes, ice_class).tolist() == [expected[c] for c in sorted(expected)]
    assert charts.ice_impact(codes, ice_class).tolist() == [expected[c] for c in sorted(expected)]


def test_classes_table_1_and_mapping():
    for name, h in TABLE_1.items():
        c = classes.get_class(name)
        assert (c.system, c.h_pass) == ("RS", h)
    assert classes.class_names("IACS") == [f"PC{n}" for n in range(1, 8)]
    assert classes.class_names("FSICR") == ["IC", "IB", "IA", "IA Super"]
    assert len(classes.CLASSES) == 13 + 7 + 4 + 1
    # Nominal IMO equivalences (sourced) and the assumed ones (flagged).
    assert classes.get_class("Arc4").polaris_class == "IA Super" and not classes.get_class("Arc4").assumed
    assert classes.get_class("Ice3").polaris_class == "IA"
    assert classes.get_class("IA Super").rs_class == "Arc4" and classes.get_class("IA").rs_class == "Ice3"
    assert [classes.get_class(f"Arc{n}").polaris_class for n in (5, 6, 7, 8, 9)] == [
        "PC6",
        "PC5",
        "PC4",
        "PC3",
        "PC2",
    ]
    assert "polaris_class" in classes.get_class("Arc7").assumed
    assert [classes.get_class(f"PC{n}").rs_class for n in range(1, 8)] == [
        "Arc9",
        "Arc8",
        "Arc7",
        "Arc6",
        "Arc5",
        "Arc4",
        "Ice3",
    ]
    assert classes.get_class("PC3").h_pass == 1.4 and "h_pass" in classes.get_class("PC3").assumed
    assert classes.get_class("IB").h_pass == 0.6  # FSICR design thickness
    # Spellings: case, spaces, the paper's 'Icebraker', 1A for IA.
    for alias, name in [
        ("arc 7", "Arc7"),
        ("ia super", "IA Super"),
        ("1A", "IA"),
        ("pc-3", "PC3"),
        ("Icebraker8", "Icebreaker8"),
        ("not ice strengthened", "none"),
    ]:
        assert classes.get_class(alias).name == name
    with pytest.raises(ValueError, match=r"ice_class must be one of \['none', 'Ice1'"):
        classes.get_class("Arc10")


def test_derived_tables_follow_the_documented_rule():
    t = impact.ICE_IMPACT
    # Open-ice classes: a stage is allowed when its upper thickness <= h_pass (Table 1).
    assert t["Ice1"][85] == 25 and t["Ice1"][88] == INF and t["Ice1"][87] == INF  # 0.4 m < 0.5 m
    assert t["Ice2"][88] == 30 and t["Ice2"][89] == INF  # stage 1 ends at 0.5 m
    assert t["Ice3"] == t["Arc4"] == t["Arc5"]  # thin FY (0.7 m) in, medium FY (1.2 m) out
    assert t["Arc6"][91] == 50  # Table 3's 30 x Table 2's 25/15
    assert t["Arc6"][86] == INF and t["Arc6"][93] == INF
    assert t["Icebreaker6"] == t["Icebreaker9"] == t["Arc7"]  # close/compact: Table 2
    assert t["none"] == {c: (1.0 if c == 55 else INF) for c in t["Arc7"]}
    # Other systems use their RS equivalent's table.
    codes = np.array([55.0, 85.0, 91.0, 93.0])
    assert ice_impact(codes, "PC3").tolist() == [2, 13, 25, 30]
    assert ice_impact(codes, "PC4").tolist() == [1, 25, 50, INF]  # PC4 -> Arc6
    assert ice_impact(codes, "IA Super").tolist() == [1, 25, INF, INF]
    assert ice_impact(codes, "none").tolist() == [1, INF, INF, INF]


def test_tables_are_editable_and_replaceable(monkeypatch):
    codes = np.array([55.0, 91.0])
    monkeypatch.setitem(impact.ICE_IMPACT, "Arc6", {**impact.ICE_IMPACT["Arc6"], 91: 40.0})
    assert ice_impact(codes, "Arc6").tolist() == [1, 40]
    monkeypatch.setitem(impact.ICE_IMPACT, "PC1", {55: 1.5, 91: 4.0})  # a table of its own
    assert ice_impact(codes, "PC1").tolist() == [1.5, 4.0]
    assert ice_impact(codes, "Arc7", table={55: 7.0, 91: 9.0}).tolist() == [7, 9]


def test_unknown_stages_are_explicit_never_open_water():
    codes = np.array([55.0, 95.0, 99.0, np.nan])
    with pytest.raises(ValueError, match=r"\[95\.0, 99\.0\].*unknown=np\.inf"):
        ice_impact(codes, "Arc9")
    assert ice_impact(codes, "Arc9", unknown=INF).tolist() == [2, INF, INF, INF]
    assert ice_impact(codes, "Arc9", unknown=40).tolist() == [2, 40, 40, INF]
    with pytest.raises(ValueError, match="unknown must be"):
        ice_impact(codes, "Arc9", unknown="open")


def test_concentration_limit_of_table_1():
    stage = np.array([87.0, 87.0, 87.0])
    ct = np.array([6.0, 7.0, 10.0])
    assert ice_impact(stage, "Arc5", concentration=ct).tolist() == [30, INF, INF]  # open ice only
    assert ice_impact(stage, "Arc7", concentration=ct).tolist() == [15, 15, INF]  # close ice
    assert ice_impact(stage, "Arc9", concentration=ct).tolist() == [15, 15, 15]  # compact ice


def test_chart_impact_on_a_sigrid_style_dataset():
    dims = ("lat", "lon")
    nan = np.nan
    ds = xr.Dataset(
        {
            "CT": (dims, [[0.0, 9.0, 9.0, nan, nan]]),
            "SA": (dims, [[nan, 91.0, nan, nan, nan]]),
            "land": (dims, [[False, False, False, False, True]]),
            "off_chart": (dims, [[False, False, False, True, False]]),
        },
        coords={"lat": [70.0], "lon": [60.0, 60.1, 60.2, 60.3, 60.4]},
    )
    assert impact.governing_stage(ds).values.tolist()[0][:3] == [55, 91, 99]
    u = impact.chart_impact(ds, "Arc7")
    assert u.values.tolist() == [[2, 25, INF, INF, INF]]  # ice of no stage: unknown -> forbidden
    assert impact.chart_impact(ds, "Arc7", unknown=30).values.tolist() == [[2, 25, 30, INF, INF]]


@pytest.fixture(scope="module")
def tongue():
    """Open water with a 2-pixel-wide tongue of first-year ice (86) from the top edge down to
    row 53 of 60: Arc5 (86 forbidden) must go around, Arc7 (u = 20) may cross."""
    stage = np.full((60, 80), 55.0)
    stage[0:54, 39:41] = 86
    return stage


def test_ice_tongue_arc7_crosses(tongue):
    r = seaway.route(ice_impact(tongue, "Arc7"), (5, 5), (5, 74), neighbourhood=5)
    assert set(r.pixels[:, 0].tolist()) == {5}  # straight along row 5
    assert (tongue[r.pixels[:, 0], r.pixels[:, 1]] == 86).sum() == 1
    # 66 pixel-lengths of open water (u 2) and 3 touching the tongue (a 2-step onto it, a
    # 1-step off it, max rule: u 20): 2*66 + 20*3.
    assert r.length == 69 and r.cost == pytest.approx(2 * 66 + 20 * 3)


@pytest.mark.parametrize("ice_class", ["Arc5", "Ice1", "PC5", "IA Super"])
def test_ice_tongue_weaker_classes_go_around(tongue, ice_class):
    u = ice_impact(tongue, ice_class)
    r = seaway.route(u, (5, 5), (5, 74), neighbourhood=5)
    assert not (tongue[r.pixels[:, 0], r.pixels[:, 1]] == 86).any()
    assert r.pixels[:, 0].max() >= 54  # round the tip
    assert r.cost == pytest.approx(r.length)  # u = 1 in open water for these classes
    assert 120 < r.length < 125
    arc7 = ice_impact(tongue, "Arc7")
    detour = sum(2 * s for s in r.step_lengths)  # Arc7 on this path pays u = 2 throughout
    assert detour > 192  # which is why Arc7 crosses instead
    assert np.isfinite(arc7[r.pixels[:, 0], r.pixels[:, 1]]).all()
