"""The speed of an ice class (knots) on one chart of a season, for seaway.icenav.season (whose
docstring describes the three models and what is closed): Andreeva 2021's V = F * V0, a user's
table by WMO stage and concentration, or the class's own model (seaway.ice.speed); 0 where the
class may not go (land, off the chart, unknown ice, over its concentration limit). Fast ice of
unknown stage takes the stage `fast_ice` says, chart by chart (seaway.ice.seasonfast)."""

from __future__ import annotations

import numpy as np

from ..errors import ChartError, SeawayError
from . import andreeva
from .classes import get_class
from .codes import ICE_FREE
from .impact import governing_stage
from .seasonfast import season_rule
from .speed import ice_speed


def _closed(frame, ct, ice_class, concentration_limit):
    """Where no class may go: land, off the chart, unknown concentration, over the class's limit."""
    shut = np.isnan(ct)
    for name in ("land", "off_chart"):
        if name in frame:
            shut |= np.asarray(frame[name].values, dtype=bool)
    if concentration_limit:
        shut |= ct > get_class(ice_class).max_concentration
    return shut


def andreeva_speed_kn(
    frame,
    ice_class,
    v0_kn,
    *,
    h_pass_m=None,
    stage_thickness=andreeva.DEFAULT_STAGE_THICKNESS,
    other_factor=1.0,
    concentration_limit=True,
    fast_ice=None,
) -> np.ndarray:
    """Andreeva 2021's V = F * V0 (knots) on one chart of a season; 0 where closed. fast_ice:
    the rule for fast ice of unknown stage (None: the season's, seaway.ice.seasonfast)."""
    ct = np.asarray(frame["CT"].values, dtype=float)
    h_pass = get_class(ice_class).h_pass if h_pass_m is None else float(h_pass_m)
    if not h_pass > 0:
        raise SeawayError(f"{get_class(ice_class).name} passes no ice (h_pass 0); give h_pass_m")
    if "thickness" in frame:
        h = np.asarray(frame["thickness"].values, dtype=float)
    else:
        h = andreeva.stage_thickness(
            governing_stage(frame, fast_ice=season_rule(frame, fast_ice)), stage_thickness
        )
    h = np.where(ct == 0, 0.0, h)
    speed = andreeva.f2(h, h_pass) * np.asarray(other_factor, dtype=float) * v0_kn
    return np.where(_closed(frame, ct, ice_class, concentration_limit), 0.0, speed)


def table_speed_kn(frame, ice_class, table, *, concentration_limit=True, fast_ice=None) -> np.ndarray:
    """Speeds (knots) from a user table on one chart: {stage: kn} or {stage: {max CT: kn}},
    read on the governing stage (fast ice of unknown stage: the `fast_ice` rule's stage)."""
    ct = np.asarray(frame["CT"].values, dtype=float)
    stage = governing_stage(frame, fast_ice=season_rule(frame, fast_ice)).values
    speed = np.zeros(ct.shape)
    known = np.isnan(stage)
    for code, entry in table.items():
        hit = stage == float(code)
        known |= hit
        if isinstance(entry, dict):
            left = hit.copy()
            for limit in sorted(entry):
                take = left & (ct <= float(limit))
                speed[take], left = float(entry[limit]), left & ~take
            speed[left] = 0.0  # concentrations above the table's last row: closed
        else:
            speed[hit] = float(entry)
    if not known.all():
        missing = sorted({float(c) for c in np.unique(stage[~known])})
        raise SeawayError(
            f"the speed table has no entry for stages {missing[:10]} met in the "
            f"season (e.g. {ICE_FREE} ice free, 99 unknown); add them (0 knots closes them)"
        )
    if not np.all(np.isfinite(speed) & (speed >= 0)):
        raise SeawayError("speeds in the table must be finite knots >= 0")
    return np.where(_closed(frame, ct, ice_class, concentration_limit), 0.0, speed)


def class_speed_kn(
    frame, ice_class, v0_kn, *, concentration_limit=True, fast_ice=None, **options
) -> np.ndarray:
    """The class's own model on one chart (knots; 0 where closed): seaway.ice.speed's Andreeva
    2021 for Register classes (with the concentration limit), IMO POLARIS for the others."""
    if get_class(ice_class).system in ("RS", "none"):
        return andreeva_speed_kn(
            frame, ice_class, v0_kn, concentration_limit=concentration_limit, fast_ice=fast_ice, **options
        )
    if "SA" not in frame:
        raise ChartError(
            f"POLARIS ({get_class(ice_class).name}) reads the stages of the ice (SA); "
            "the season has none: give a Register class, or speed='andreeva'"
        )
    v = np.asarray(ice_speed(frame, ice_class, v0_kn, fast_ice=season_rule(frame, fast_ice)).values, float)
    return np.where(_closed(frame, np.asarray(frame["CT"].values, float), ice_class, False), 0.0, v)


def curve_speed_kn(
    frame, ice_class, v0_kn, curve, *, concentration_limit=False, fast_ice=None, **options
) -> np.ndarray:
    """A ship's own ice curve on one chart (knots; 0 where closed): seaway.ice.speed with the
    curve (the concentration acts through the equivalent thickness; the class's concentration
    limit only when asked)."""
    rule = season_rule(frame, fast_ice)
    v = np.asarray(ice_speed(frame, ice_class, v0_kn, curve=curve, fast_ice=rule, **options).values, float)
    ct = np.asarray(frame["CT"].values, float)
    return np.where(_closed(frame, ct, ice_class, concentration_limit), 0.0, v)


def is_curve(speed) -> bool:
    """Is a season's speed model a ship's ice curve (an object with speed() and describe())?"""
    return callable(getattr(speed, "speed", None)) and callable(getattr(speed, "describe", None))


def frame_speed_kn(frame, ice_class, v0_kn, speed, **options) -> np.ndarray:
    """The speed (knots; 0 where closed) on one chart by the season's speed model: speed
    'class' (class_speed_kn), 'andreeva' (andreeva_speed_kn), a ship's ice curve
    (curve_speed_kn) or a table (table_speed_kn)."""
    if is_curve(speed):
        return curve_speed_kn(frame, ice_class, v0_kn, speed, **options)
    if speed == "class":
        return class_speed_kn(frame, ice_class, v0_kn, **options)
    if isinstance(speed, str):
        return andreeva_speed_kn(frame, ice_class, v0_kn, **options)
    return table_speed_kn(frame, ice_class, speed, **options)
