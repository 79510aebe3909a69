"""Paper 002 (Andreeva): f1, f2, f3, F, V = F*V0, T; the twelve-route table; the Pareto set;
and the F-threshold sweep on a chart."""

import numpy as np
import pytest

from seaway.ice import andreeva as a
from seaway.icenav import pareto

# Paper 002, "Параметры маршрутов": route, l (nm), Z (m), h (m), f1, f2, F, V (kn), T (h).
# Arc7, draft 12 m, h_pass 1.7 m, V0 12 kn, f3 = 1, dL = 0 (the table's f1 is 1 - d/Z).
TABLE = [
    ("I", 200, 50, 1.30, 0.76, 0.23, 0.17, 2.0, 100),
    ("II", 210, 50, 1.30, 0.76, 0.23, 0.17, 2.0, 105),
    ("III", 220, 40, 1.20, 0.70, 0.29, 0.20, 2.4, 92),
    ("IV", 230, 30, 1.10, 0.60, 0.35, 0.21, 2.5, 92),
    ("V", 240, 30, 1.00, 0.60, 0.41, 0.25, 3.0, 80),
    ("VI", 250, 30, 0.90, 0.60, 0.47, 0.28, 3.4, 74),
    ("VII", 260, 30, 0.80, 0.60, 0.53, 0.32, 3.8, 68),
    ("VIII", 270, 24, 0.60, 0.50, 0.64, 0.32, 3.8, 71),
    ("IX", 280, 22, 0.50, 0.45, 0.70, 0.32, 3.8, 74),
    ("X", 290, 20, 0.40, 0.40, 0.76, 0.30, 3.6, 80),
    ("XI", 300, 18, 0.40, 0.33, 0.76, 0.25, 3.0, 100),
    ("XII", 310, 10, 0.40, 0.00, 0.76, 0.00, 0.0, np.inf),
]
SHIP = {"draft": 12.0, "h_pass": 1.7, "v0_kn": 12.0}


@pytest.mark.parametrize("row", TABLE, ids=[r[0] for r in TABLE])
def test_twelve_route_table(row):
    """The paper computes each column from the previous ones already rounded to two digits,
    and cuts some f2 values instead of rounding them (0.2353 -> 0.23, 0.647 -> 0.64,
    0.706 -> 0.70): so f1, f2 and F are within one unit of the last printed digit of the exact
    values, and F, V, T follow from the printed columns to the printed precision."""
    _, l_nm, z, h, f1, f2, F, V, T = row
    exact = a.route_row(l_nm, z, h, **SHIP)
    assert exact["f1"] == pytest.approx(f1, abs=0.01)
    assert exact["f2"] == pytest.approx(f2, abs=0.01)
    assert exact["F"] == pytest.approx(F, abs=0.01)
    # Step by step from the printed columns, with the model's own functions.
    assert float(a.f1(12.0, z)) * f2 == pytest.approx(F, abs=0.0051) or f1 == 0
    assert float(a.f1(12.0, z)) == pytest.approx(f1, abs=0.005)
    assert F * SHIP["v0_kn"] == pytest.approx(V, abs=0.05)
    if V > 0:
        # Whole hours; route X prints 80 for 290/3.6 = 80.6.
        assert l_nm / V == pytest.approx(T, abs=0.6)
        assert exact["T"] == pytest.approx(l_nm / (exact["F"] * 12.0))
    else:
        assert exact["T"] == np.inf and exact["V"] == 0


def test_route_vii_is_the_papers_optimum():
    times = [r[8] for r in TABLE]
    safety = [r[6] for r in TABLE]
    assert [TABLE[i][0] for i in a.pareto_front(times, safety)] == ["VII"]
    # With exact (unrounded) values route VIII (F 0.324 > 0.318) joins the front.
    exact = [a.route_row(r[1], r[2], r[3], **SHIP) for r in TABLE]
    front = a.pareto_front([e["T"] for e in exact], [e["F"] for e in exact])
    assert [TABLE[i][0] for i in front] == ["VII", "VIII"]
    assert exact[6]["T"] == pytest.approx(260 / (0.6 * (1 - 0.8 / 1.7) * 12))


def test_factors_edges_and_survey_correction():
    assert a.survey_correction(500) == pytest.approx(1.5)  # paper 002's examples
    assert a.survey_correction(2000) == pytest.approx(6.0)
    assert a.survey_correction(0) == 0  # multibeam
    assert a.survey_correction(np.inf, depth=30.0) == 30.0  # no survey: dL = Z
    assert float(a.f1(12, 30, a.survey_correction(np.inf, depth=30.0))) == 0
    assert float(a.f1(12, 50, 1.5)) == pytest.approx(1 - 12 / 48.5)
    assert a.f1(12, np.array([12.0, 11.0, np.nan, 24.0])).tolist() == [0, 0, 0, 0.5]
    assert a.f2(np.array([0.0, 0.85, 1.7, 2.0, np.nan]), 1.7).tolist() == [1, 0.5, 0, 0, 0]
    assert a.f3(np.array([50.0, 100.0, 150.0]), 100.0).tolist() == [0.5, 1.0, 0.0]
    F = a.safety_factor(draft=12, depth=30, thickness=0.8, h_pass=1.7, f3_value=0.5)
    assert float(F) == pytest.approx(0.6 * (1 - 0.8 / 1.7) * 0.5)
    cost = a.time_cost(np.array([0.5, 0.0]), 10.0)
    assert cost[0] == pytest.approx(1 / (5 * 1.852)) and cost[1] == np.inf


def test_pareto_sweep_on_a_chart():
    """A planar chart of 1 km pixels like the paper's figure: ports in safe water (F 0.9) west
    and east, thick ice between them (F 0.3), and thinner ice (F 0.35) further south: the
    short route is faster, the detour safer."""
    F = np.full((30, 60), 0.3)
    F[22:, :] = 0.35
    F[:, :10] = 0.9
    F[:, 50:] = 0.9
    out = pareto.pareto_routes(F, (5, 1), (5, 58), v0_kn=10.0, neighbourhood=5)
    assert [p.safety for p in out] == [0.3, 0.35]  # the 0.9 threshold closes the way
    fast, safe = out
    assert (fast.threshold, safe.threshold) == (0.3, 0.35)
    assert fast.time < safe.time
    assert set(fast.route.pixels[:, 0].tolist()) == {5} and fast.route.length == 57
    assert safe.route.pixels[:, 0].max() == 22 and safe.route.length > 75
    kmh = 10.0 * 1.852
    # 57 km: between 40 and 43 km at F 0.3 (the max rule), the rest at 0.9.
    assert 40 / (0.3 * kmh) + 17 / (0.9 * kmh) <= fast.time <= 43 / (0.3 * kmh) + 14 / (0.9 * kmh)
    assert fast.time == pytest.approx(fast.route.cost) and safe.time == pytest.approx(safe.route.cost)
    with pytest.raises(ValueError, match="impassable"):
        pareto.pareto_routes(np.zeros((5, 5)), (0, 0), (4, 4), v0_kn=10.0, thresholds=[0.1])
