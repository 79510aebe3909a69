"""IMO POLARIS (MSC.1/Circ.1519, 2016): Risk Index Values, Risk Index Outcome, operation levels,
speed limits, and a time-cost raster where "special consideration" is impassable.

RIO = sum_i C_i * RIV_i over the ice types of a pixel, C_i in tenths, with the open water
(10 - CT tenths) counted as ice free. RIO >= 0: normal operation. PC1-PC7: -10 <= RIO < 0
elevated risk (speed limit PC1 11 kn, PC2 8 kn, PC3-PC5 5 kn, PC6-PC7 3 kn), RIO < -10 special
consideration. Classes below PC7: any RIO < 0 is special consideration.

Which POLARIS column each WMO stage uses (STAGE_COLUMN, editable): where a stage spans two
columns the thicker is taken (conservative): young ice (83) -> grey-white, thin first-year
(87) -> TFY 2nd stage, undivided first-year (86) -> thick FY, medium FY (91) -> MFY (not
"MFY < 1 m"), old ice (95) and multi-year (97) -> heavy multi-year, glacier ice (98) -> heavy
multi-year (the circular's usual practice). Unknown stage (99, or ice of no stage) ->
`unknown_column` (HMY by default); unknown concentration -> `unknown_concentration` tenths
(10 by default). Nothing unknown is ever counted as open water.
"""

from __future__ import annotations

import numpy as np

from .classes import get_class

KM_PER_NM = 1.852
COLUMNS = ("IF", "new", "grey", "GW", "TFY1", "TFY2", "MFY<1m", "MFY", "ThFY", "SY", "LMY", "HMY")
#: MSC.1/Circ.1519, Table 1.3: RIV by class (row) and ice type (COLUMNS).
RIV = {
    "PC1": (3, 3, 3, 3, 2, 2, 2, 2, 2, 2, 1, 1),
    "PC2": (3, 3, 3, 3, 2, 2, 2, 2, 2, 1, 1, 0),
    "PC3": (3, 3, 3, 3, 2, 2, 2, 2, 2, 1, 0, -1),
    "PC4": (3, 3, 3, 3, 2, 2, 2, 2, 1, 0, -1, -2),
    "PC5": (3, 3, 3, 3, 2, 2, 1, 1, 0, -1, -2, -2),
    "PC6": (3, 2, 2, 2, 2, 1, 1, 0, -1, -2, -3, -3),
    "PC7": (3, 2, 2, 2, 1, 1, 0, -1, -2, -3, -3, -3),
    "IA Super": (3, 2, 2, 2, 2, 1, 0, -1, -2, -3, -4, -4),
    "IA": (3, 2, 2, 2, 1, 0, -1, -2, -3, -4, -5, -5),
    "IB": (3, 2, 2, 1, 0, -1, -2, -3, -4, -5, -6, -6),
    "IC": (3, 2, 1, 0, -1, -2, -3, -4, -5, -6, -7, -8),
    "not ice strengthened": (3, 1, 0, -1, -2, -3, -4, -5, -6, -7, -8, -8),
}
#: WMO stage code -> POLARIS column (see the module docstring for the conservative choices).
STAGE_COLUMN = {
    55: "IF",
    81: "new",
    82: "new",
    84: "grey",
    83: "GW",
    85: "GW",
    88: "TFY1",
    89: "TFY2",
    87: "TFY2",
    91: "MFY",
    86: "ThFY",
    93: "ThFY",
    96: "SY",
    95: "HMY",
    97: "HMY",
    98: "HMY",
}
#: Speed limit (knots) under elevated risk, MSC.1/Circ.1519 Table 1.4.
SPEED_LIMIT_KN = {"PC1": 11.0, "PC2": 8.0, "PC3": 5.0, "PC4": 5.0, "PC5": 5.0, "PC6": 3.0, "PC7": 3.0}
NORMAL, ELEVATED, SPECIAL = 0, 1, 2
LEVEL_NAMES = ("normal operation", "elevated risk", "special consideration")


def riv_row(ice_class) -> dict:
    """{column: RIV} for a class (any name seaway.ice.classes knows; RS classes use their
    polaris_class, an assumption documented there)."""
    return dict(zip(COLUMNS, RIV[get_class(ice_class).polaris_class]))


def stage_riv(stage, ice_class, unknown_column="HMY") -> np.ndarray:
    """RIV of each WMO stage code in `stage` (array); NaN and codes without a column (99, 80)
    take `unknown_column`."""
    row = riv_row(ice_class)
    codes = np.asarray(stage, dtype=float)
    out = np.full(codes.shape, float(row[unknown_column]))
    for code, column in STAGE_COLUMN.items():
        out[codes == code] = row[column]
    return out


def rio(ct, partials, ice_class, *, unknown_concentration=10.0, unknown_column="HMY"):
    """Risk Index Outcome of each pixel.

    ct: total concentration (tenths); partials: [(C_A, S_A), (C_B, S_B), ...] concentration
    (tenths) and WMO stage arrays, thickest first. A NaN partial concentration of a present
    stage, or any CT not accounted for by the partials, is given to S_A (the thickest ice:
    conservative). NaN CT -> `unknown_concentration`. Returns float64 RIO (same shape)."""
    ct = np.asarray(ct, dtype=float)
    ct = np.where(np.isnan(ct), float(unknown_concentration), ct)
    row = riv_row(ice_class)
    total = (10.0 - ct) * row["IF"]
    known = np.zeros(ct.shape)
    first_stage = None
    for c, s in partials:
        s = np.broadcast_to(np.asarray(s, dtype=float), ct.shape)
        c = np.broadcast_to(np.asarray(c, dtype=float), ct.shape)
        riv = stage_riv(s, ice_class, unknown_column)
        use = np.where(np.isnan(c) | np.isnan(s), 0.0, c)
        total = total + use * riv
        known = known + use
        if first_stage is None:
            first_stage = s
    rest = np.maximum(ct - known, 0.0)
    if first_stage is None:
        first_stage = np.full(ct.shape, np.nan)
    return total + rest * stage_riv(first_stage, ice_class, unknown_column)


def rio_egg(ice_class, ct, *pairs, **kwargs) -> float:
    """RIO of one egg code: rio_egg('PC5', 9, (5, 93), (4, 91)) for CT 9/10 of which 5/10
    thick and 4/10 medium first-year ice."""
    partials = [(np.float64(c), np.float64(s)) for c, s in pairs]
    return float(rio(np.float64(ct), partials, ice_class, **kwargs))


def operation_level(rio_values, ice_class) -> np.ndarray:
    """0 normal, 1 elevated risk, 2 special consideration (int8), per MSC.1/Circ.1519."""
    r = np.asarray(rio_values, dtype=float)
    pc = get_class(ice_class).polaris_class in SPEED_LIMIT_KN
    level = np.where(r >= 0, NORMAL, ELEVATED if pc else SPECIAL)
    if pc:
        level = np.where(r < -10, SPECIAL, level)
    return level.astype(np.int8)


def speed_limit_kn(ice_class) -> float:
    """The circular's speed limit under elevated risk (kn); inf for classes below PC7 (which
    have no elevated-risk level)."""
    return SPEED_LIMIT_KN.get(get_class(ice_class).polaris_class, float("inf"))


def polaris_chart(
    ds, ice_class, *, v0_kn=12.0, elevated_penalty=2.0, unknown_concentration=10.0, unknown_column="HMY"
):
    """POLARIS layers for a SIGRID-style chart Dataset (CT, CA/SA, CB/SB, CC/SC, land):

    rio; level (0/1/2); speed_kn = v0_kn in normal operation, min(v0_kn, limit) under elevated
    risk, 0 under special consideration; cost = elevated_penalty (1 under normal operation)
    / (speed_kn * 1.852), in hours per km, inf where special consideration, on land or off the
    chart. Route on `cost` and the route cost is (penalised) hours on geographic charts."""
    names = [("CA", "SA"), ("CB", "SB"), ("CC", "SC")]
    partials = [(ds[c].values, ds[s].values) for c, s in names if c in ds and s in ds]
    ct = ds["CT"].values
    r = rio(
        ct, partials, ice_class, unknown_concentration=unknown_concentration, unknown_column=unknown_column
    )
    level = operation_level(r, ice_class)
    limit = speed_limit_kn(ice_class)
    speed = np.where(level == NORMAL, v0_kn, np.where(level == ELEVATED, min(v0_kn, limit), 0.0))
    with np.errstate(divide="ignore"):
        cost = np.where(level == ELEVATED, elevated_penalty, 1.0) / (speed * KM_PER_NM)
    blocked = ds["land"].values.astype(bool)
    if "off_chart" in ds:
        blocked |= ds["off_chart"].values
    cost[blocked] = np.inf
    r[blocked] = np.nan
    out = ds[["land"]].copy()
    dims = ds["CT"].dims
    cls = get_class(ice_class)
    out["rio"] = (
        dims,
        r,
        {"long_name": f"POLARIS risk index outcome, {cls.polaris_class} RIVs", "units": "1"},
    )
    out["level"] = (
        dims,
        level,
        {
            "long_name": "POLARIS operation level",
            "flag_values": np.array([0, 1, 2], np.int8),
            "flag_meanings": "normal elevated_risk special_consideration",
        },
    )
    out["speed_kn"] = (dims, speed, {"long_name": "permitted speed", "units": "knot"})
    out["cost"] = (dims, cost, {"long_name": "time per km (elevated risk penalised)", "units": "h km-1"})
    out.attrs.update(
        ice_class=cls.name, polaris_class=cls.polaris_class, elevated_penalty=elevated_penalty, v0_kn=v0_kn
    )
    return out
