"""Grinyak et al. 2022's ice impact u(x, y): Tables 2 and 3 exactly, tables for the other classes by a
documented rule, and rasters of u for a vessel.

Grinyak et al. 2022 (Grinyak et al. 2022) gives u only for "Arc7 and stronger" (Table 2) and Arc5
(Table 3), by ice type. Rule used here for the other Russian Register classes (DERIVATION):

1. Classes that Table 1 allows into close or compact ice (Arc7, Arc8, Arc9, Icebreaker6-9) use
   Table 2: the paper says it holds for "Arc7 and stronger".
2. Classes limited to open ice (Ice1-Arc6) may enter a stage only when the stage's largest
   typical thickness (seaway.ice.codes.STAGE_CODES) is at most the class's thickness h_pass
   (Table 1). For Arc5 (1.0 m) this gives exactly Table 3's infinities (first-year ice to 2.0 m,
   medium first-year to 1.2 m and thick first-year are out; thin first-year, to 0.7 m, is in).
3. An allowed stage takes Table 3's value. A stage Table 3 forbids but the class may enter
   (only medium first-year ice for Arc6, 1.3 m) takes Table 3's thin first-year value scaled by
   Table 2's ratio for that stage: 30 x 25/15 = 50.
4. A vessel that is not ice-strengthened ('none', h_pass 0) may enter only ice-free water (1).
5. IACS and Finnish-Swedish classes use the table of their RS equivalent (seaway.ice.classes).

Old ice, glacier ice and 'unknown' (95-99) are in neither paper table, so no table has them:
`ice_impact` raises on them unless you say what they cost (`unknown=`), and `chart_impact`
makes them impassable by default. Tables are plain dicts (WMO code -> u) in ICE_IMPACT: edit
them, add a class, or pass your own with `table=`.
"""

from __future__ import annotations

import numpy as np

from ..errors import ChartError, SeawayError
from .classes import CLASSES, IceClass, class_names, get_class
from .codes import ICE_FREE, STAGE_CODES, UNKNOWN_STAGE
from .forms import DEFAULT_FAST_ICE, fast_ice_stage, free_water_rule

INF = float("inf")
#: Grinyak et al. 2022, Table 2 ("Arc7 and stronger"), by WMO stage code. The paper's "thin" (тонкий) is
#: thin first-year ice (87, with its stages 88 and 89), "first-year" (однолетний) the undivided
#: 86, "medium" 91, "thick" 93; "new ice" (начальные виды) 81.
TABLE_2 = {
    55: 2.0,
    81: 3.0,
    82: 5.0,
    84: 8.0,
    83: 10.0,
    85: 13.0,
    87: 15.0,
    88: 15.0,
    89: 15.0,
    86: 20.0,
    91: 25.0,
    93: 30.0,
}
#: Grinyak et al. 2022, Table 3 (Arc5).
TABLE_3 = {
    55: 1.0,
    81: 3.0,
    82: 5.0,
    84: 10.0,
    83: 15.0,
    85: 25.0,
    87: 30.0,
    88: 30.0,
    89: 30.0,
    86: INF,
    91: INF,
    93: INF,
}


def derive_table(ice_class) -> dict:
    """Impact table (WMO code -> u) of an RS class by the module's rule (Grinyak et al. 2022 + Table 1)."""
    cls = get_class(ice_class)
    if cls.system != "RS" and cls.name != "none":
        cls = CLASSES[cls.rs_class]
    if cls.max_concentration >= 8.0:  # close or compact ice: "Arc7 and stronger"
        return dict(TABLE_2)
    table = {}
    for code, table3 in TABLE_3.items():
        upper = STAGE_CODES[code][1][1]
        if upper > cls.h_pass:
            table[code] = INF
        elif np.isfinite(table3):
            table[code] = table3
        else:
            table[code] = TABLE_3[87] * TABLE_2[code] / TABLE_2[87]
    return table


#: Impact tables by class name, for every RS class and 'none' (derived; Arc7 and Arc5 are the
#: paper's tables exactly). Other classes use their RS equivalent's entry unless you add one.
ICE_IMPACT = {name: derive_table(name) for name in class_names("RS") + ["none"]}


def table_for(ice_class) -> dict:
    """The table ice_impact uses for a class: ICE_IMPACT[name], else its RS equivalent's."""
    cls = get_class(ice_class)
    table = ICE_IMPACT.get(cls.name)
    return table if table is not None else ICE_IMPACT[str(cls.rs_class)]


def ice_impact(stage, ice_class="Arc7", *, table=None, unknown="raise", concentration=None):
    """Grinyak et al. 2022's impact u (cost per unit length, dimensionless) of each pixel's WMO stage of
    development for a vessel of `ice_class` (any name of seaway.ice.classes); inf where the
    class may not go.

    stage: array or DataArray of SIGRID-3 stage codes; NaN (land, outside the chart) -> inf.
    table: a dict code -> u to use instead of the class's table (ICE_IMPACT).
    unknown: what a code missing from the table costs: 'raise' (ValueError, the default) or a
        number (np.inf to forbid it, e.g. for old ice or 'unknown' 99).
    concentration: optional total concentration (tenths, same shape); pixels whose
        concentration exceeds the class's max_concentration (Grinyak et al. 2022 Table 1) become inf.
    Returns float64 u of the same shape (a DataArray, with attributes, for a DataArray)."""
    cls = get_class(ice_class)
    if table is None:
        table = table_for(cls)
    codes = np.asarray(stage.values if hasattr(stage, "dims") else stage, dtype=float)
    known = np.isnan(codes)
    u = np.full(codes.shape, INF)
    for code, value in table.items():
        hit = codes == code
        u[hit] = value
        known |= hit
    if not known.all():
        bad = sorted({float(c) for c in np.unique(codes[~known])})
        if isinstance(unknown, str):
            if unknown != "raise":
                raise SeawayError(f"unknown must be 'raise' or a number, got {unknown!r}")
            raise ChartError(
                f"stage codes {bad[:10]} have no impact for {cls.name}; known WMO "
                f"codes: {sorted(table)} (NaN is impassable). Pass unknown=np.inf "
                "to forbid them or unknown=<u> to cost them"
            )
        u[~known] = float(unknown)
    if concentration is not None:
        c = np.asarray(getattr(concentration, "values", concentration), dtype=float)
        u[c > cls.max_concentration] = INF
    if hasattr(stage, "dims"):
        out = stage.copy(data=u)
        out.name = "ice_impact"
        out.attrs = {
            "long_name": f"ice impact u for a {cls.name} vessel (Grinyak et al. 2022)",
            "units": "1",
            "ice_class": cls.name,
        }
        return out
    return u


def governing_stage(ds, unknown_stage=UNKNOWN_STAGE, *, fast_ice=DEFAULT_FAST_ICE):
    """One stage per pixel of a SIGRID-style chart (seaway.ice.sigrid): SA (the thickest stage,
    SIGRID-3 order) where there is ice, 55 where CT is 0 and in open or bergy water (CT codes
    01/02), `unknown_stage` (99) where there is ice of no known stage or the concentration is
    unknown; NaN on land and off the chart. Fast ice (FA 08) of unknown stage takes the stage
    `fast_ice` says (seaway.ice.forms: "nearby" by default, a WMO code, or "closed": NaN, i.e.
    impassable). The result's attribute ``assumptions`` (a tuple of sentences) says what was
    assumed."""
    ct, sa = ds["CT"].values, ds["SA"].values
    stage = np.where(ct == 0, float(ICE_FREE), sa)
    stage = np.where((ct > 0) & np.isnan(sa), float(unknown_stage), stage)
    off = ds["off_chart"].values if "off_chart" in ds else np.zeros(ct.shape, bool)
    stage = np.where(np.isnan(ct) & ~off, float(unknown_stage), stage)
    free, free_note = free_water_rule(ds)
    stage = np.where(free, float(ICE_FREE), stage)
    code, fast_note, fast = fast_ice_stage(ds, fast_ice)
    blocked = ds["land"].values | off | (fast if code is None else np.zeros(ct.shape, bool))
    stage = np.where(fast & ~blocked, code if code is not None else np.nan, stage)
    out = ds["CT"].copy(data=np.where(blocked, np.nan, stage)).rename("stage_of_development")
    out.attrs = {
        "long_name": "governing stage of development (WMO code)",
        "units": "1",
        "assumptions": tuple(n for n in (fast_note, free_note) if n),
    }
    return out


def chart_impact(
    ds, ice_class="Arc7", *, unknown=INF, table=None, use_concentration=False, fast_ice=DEFAULT_FAST_ICE
):
    """u for a SIGRID-style chart Dataset: ice_impact of governing_stage(ds, fast_ice=...); land,
    ice shelves and pixels off the chart are inf; stages the table lacks (old ice, glacier ice
    at 1/10 or more, 99) cost `unknown` (impassable by default: conservative, never open water).
    Fast ice, bergy water and icebergs follow seaway.ice.forms; what was assumed is in the
    result's ``assumptions`` attribute (and in Route.assumptions of routes found on it)."""
    stage = governing_stage(ds, fast_ice=fast_ice)
    u = ice_impact(
        stage, ice_class, table=table, unknown=unknown, concentration=ds["CT"] if use_concentration else None
    )
    u.attrs["assumptions"] = stage.attrs["assumptions"]
    return u


__all__ = [
    "TABLE_2",
    "TABLE_3",
    "ICE_IMPACT",
    "derive_table",
    "table_for",
    "ice_impact",
    "governing_stage",
    "chart_impact",
    "IceClass",
]
