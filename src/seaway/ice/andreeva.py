"""Andreeva 2021 (Andreeva): ship speed V = F * V0 with F = f1 * f2 * f3, time T = l / V, and the
Pareto set between time and safety (a route's safety is the lowest F met along it).

Equation 9 of the paper:
  f1 = 1 - d / (Z - dL)   depth: d draft (m), Z charted depth (m), dL survey correction (m);
                          0 when d >= Z - dL.
  f2 = 1 - h / h_pass     ice: h thickness (m), h_pass the thickness the ship passes (m);
                          0 when h >= h_pass.
  f3 = 1 - (1 - B / B0)   fairway: B the width of the ship's safe lane, B0 the fairway width;
                          0 when B > B0. Eq. 9 reduces to B / B0, which the paper's own text
                          (F = 1 when B = B0, F = 0 when B -> 0) agrees with; its physical
                          reading is unclear, so pass f3 directly if you have your own.
  dL = k * L (eq. 5), k <= 0.006 on the Northern Sea Route; the paper's examples (1.5 m for
  500 m between survey lines, 6 m for 2000 m) take L as half the line spacing. dL = Z where
  no survey exists (f1 = 0), 0 for a multibeam survey.

Units: speeds in knots, lengths in nautical miles give T in hours; on geographic charts the
engine measures km, so time_cost() returns hours per km (1 nm = 1.852 km).
"""

from __future__ import annotations

import numpy as np

from ..base.units import KM_PER_NM
from ..errors import SeawayError
from .codes import STAGE_CODES

NSR_K = 0.006  # Andreeva 2021: largest vertical roughness index at 95 % on the NSR


def survey_correction(line_spacing_m, k=NSR_K, depth=None):
    """dL (m) for a survey with `line_spacing_m` between sounding lines (Andreeva 2021, eq. 5 with
    L = half the spacing): 500 m -> 1.5 m, 2000 m -> 6 m. inf spacing (no survey) -> `depth`
    (so f1 = 0); 0 (multibeam) -> 0."""
    spacing = np.asarray(line_spacing_m, dtype=float)
    dl = k * spacing / 2.0
    if depth is not None:
        dl = np.where(np.isinf(spacing), np.asarray(depth, dtype=float), dl)
    return dl


def f1(draft, depth, delta_l=0.0):
    """Depth factor 1 - d / (Z - dL), clipped to [0, 1]; 0 where d >= Z - dL or Z is NaN."""
    avail = np.asarray(depth, dtype=float) - np.asarray(delta_l, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        f = np.where(avail > draft, 1.0 - draft / avail, 0.0)
    return np.clip(np.nan_to_num(f, nan=0.0), 0.0, 1.0)


def depth_factor(depth, draft, delta_l=0.0):
    """f1 on a chart from a depth raster instead of one charted depth: `depth` in m, positive
    down, e.g. seaway.depth.depth_on_grid(seaway.depth.open_bathymetry(path), chart) (the
    shallowest depth in each pixel); unknown depth (NaN) and land give f1 = 0, so V = 0 there.
    A DataArray in gives a DataArray named f1 on the same grid."""
    values = np.asarray(getattr(depth, "values", depth), dtype=float)
    f = f1(draft, values, delta_l)
    if hasattr(depth, "dims"):
        out = depth.copy(data=f)
        out.name = "f1"
        out.attrs = {
            "long_name": "depth factor 1 - d / (Z - dL) (Andreeva 2021, eq. 9)",
            "units": "1",
            "draft_m": float(draft),
        }
        return out
    return f


def f2(thickness, h_pass):
    """Ice factor 1 - h / h_pass, clipped to [0, 1]; 0 where h >= h_pass or h is NaN."""
    h = np.asarray(thickness, dtype=float)
    f = np.where(h < h_pass, 1.0 - h / h_pass, 0.0)
    return np.clip(np.nan_to_num(f, nan=0.0), 0.0, 1.0)


#: The default thickness of a stage of development: the middle of its WMO range (WMO-No. 259): a
#: chart of stages gives no thickness, and the middle is the expected value within the range;
#: "upper" is the conservative bound (thick first-year 2.0 m closes it to Arc7 under Andreeva's
#: f2), "lower" the optimistic one.
DEFAULT_STAGE_THICKNESS = "mid"
STAGE_THICKNESS_RULES = ("lower", "mid", "upper")


def stage_thickness(stage, rule=DEFAULT_STAGE_THICKNESS) -> np.ndarray:
    """Typical thickness h (m) of WMO stage codes (seaway.ice.codes.STAGE_CODES) by `rule`: the
    middle of the WMO-No. 259 range ("mid", the default), its upper end ("upper", conservative:
    thick first-year 2.0 m) or lower end ("lower"), or a dict {stage code: metres} for the stages
    it names, the middle for the others; 0 for ice free (55); NaN for stages without a thickness
    (old ice, glacier ice, unknown), so f2 = 0 there; multi-year ice (no upper end) gives inf
    except by its lower end."""
    table = check_stage_thickness(rule)
    base = "mid" if isinstance(table, dict) else table
    codes = np.asarray(getattr(stage, "values", stage), dtype=float)
    h = np.full(codes.shape, np.nan)
    for code, (_, (lo, hi)) in STAGE_CODES.items():
        h[codes == code] = {"upper": hi, "lower": lo, "mid": 0.5 * (lo + hi)}[base]
    for code, metres in table.items() if isinstance(table, dict) else ():
        h[codes == code] = metres
    return h


def check_stage_thickness(rule):
    """The rule of stage_thickness, checked: "lower", "mid", "upper" or {WMO stage: metres}."""
    if isinstance(rule, str) and rule in STAGE_THICKNESS_RULES:
        return rule
    if isinstance(rule, dict) and rule:
        out = {}
        for code, metres in rule.items():
            try:
                c, m = float(code), float(metres)
            except (TypeError, ValueError):
                c, m = float("nan"), float("nan")
            if c not in STAGE_CODES or not (0 <= m <= 10):
                raise SeawayError(
                    f"stage thickness {code!r}: {metres!r} is not a WMO stage code and a thickness in m "
                    "(0-10), e.g. {93: 1.5}"
                )
            out[c] = m
        return out
    raise SeawayError(
        f"stage_thickness must be one of {', '.join(STAGE_THICKNESS_RULES)} or a table "
        f"{{WMO stage: metres}}, e.g. {{93: 1.5}}; got {rule!r}"
    )


def stage_thickness_words(stage, rule=DEFAULT_STAGE_THICKNESS) -> str:
    """Which thickness each stage found in `stage` takes under `rule`, and why, in words."""
    codes = np.asarray(getattr(stage, "values", stage), dtype=float)
    present = [c for c in sorted(STAGE_CODES) if c not in (55, 99) and np.any(codes == c)]
    h = stage_thickness(np.array(present, float), rule)
    table = check_stage_thickness(rule)
    how = (
        "as given, the middle of the WMO range for the others"
        if isinstance(table, dict)
        else {"mid": "the middle", "upper": "the upper end", "lower": "the lower end"}[table]
        + " of its WMO range"
    )
    each = ", ".join(f"{STAGE_CODES[c][0]} {v:.2f} m" for c, v in zip(present, h) if np.isfinite(v))
    return (
        f"thickness from the stage of development, {how} (WMO-No. 259): {each or 'no stage with a thickness'}"
    )


def f3(lane_width, fairway_width):
    """Fairway factor of eq. 9, 1 - (1 - B / B0) = B / B0, in [0, 1]; 0 where B > B0."""
    b, b0 = np.asarray(lane_width, dtype=float), np.asarray(fairway_width, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        f = np.where(b <= b0, 1.0 - (1.0 - b / b0), 0.0)
    return np.clip(np.nan_to_num(f, nan=0.0), 0.0, 1.0)


def safety_factor(*, draft, depth, thickness, h_pass, delta_l=0.0, f3_value=1.0):
    """F = f1 * f2 * f3 (Andreeva 2021, eq. 8-9), elementwise."""
    return f1(draft, depth, delta_l) * f2(thickness, h_pass) * np.asarray(f3_value, dtype=float)


def route_row(l_nm, depth, thickness, *, draft, h_pass, v0_kn, delta_l=0.0, f3_value=1.0):
    """One row of Andreeva 2021's route table for a route of `l_nm` nautical miles with one depth
    (m) and one ice thickness (m): dict f1, f2, F, V (kn), T (h; inf when F = 0). Exact values:
    the paper prints them rounded to two digits, computing each column from the previous
    columns already rounded."""
    a, b = float(f1(draft, depth, delta_l)), float(f2(thickness, h_pass))
    f = a * b * float(f3_value)
    v = f * v0_kn
    return {"f1": a, "f2": b, "F": f, "V": v, "T": l_nm / v if v > 0 else float("inf")}


def time_cost(F, v0_kn):
    """Hours per km at speed F * v0_kn (knots); inf where F = 0 (the route is forbidden there)."""
    speed = np.asarray(getattr(F, "values", F), dtype=float) * v0_kn * KM_PER_NM
    with np.errstate(divide="ignore"):
        cost = np.where(speed > 0, 1.0 / np.where(speed > 0, speed, 1.0), np.inf)
    if hasattr(F, "dims"):
        out = F.copy(data=cost)
        out.name = "time_cost"
        out.attrs = {"long_name": "time per unit length at V = F*V0 (Andreeva 2021)", "units": "h km-1"}
        return out
    return cost


def pareto_front(times, safeties) -> list:
    """Indices of the non-dominated (time, safety) pairs: no other has time <= and safety >=
    with one strict (Andreeva 2021, eq. 10). Infinite times are never kept. Sorted by time."""
    t, s = np.asarray(times, dtype=float), np.asarray(safeties, dtype=float)
    keep = []
    for i in range(len(t)):
        if not np.isfinite(t[i]):
            continue
        dominated = (t <= t[i]) & (s >= s[i]) & ((t < t[i]) | (s > s[i]))
        if not dominated.any():
            keep.append(i)
    return sorted(keep, key=lambda i: (t[i], -s[i]))
