"""SIGRID-3 codes: stages of development and concentrations, and how messy real values decode.

Source: JCOMM Technical Report No. 23, "SIGRID-3: a vector archive format for sea ice charts"
(v3.0, 2014), and the WMO Sea-Ice Nomenclature (WMO No. 259) for the typical thicknesses.

Real charts write codes as text, sometimes without the leading zero ('1' for '01'), use -9
(not applicable / missing) and 99 (unknown), NULL on land, and range codes such as '57'
(5 to 7 tenths). `parse_code` and `concentration_tenths` decode all of these; nothing unknown
is ever decoded as open water.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import SeawayError

#: WMO stage of development (SIGRID-3 SA/SB/SC codes) -> (name, (min, max) typical thickness
#: in m). Thick first-year ice is "> 120 cm"; first-year ice ends at 2 m, so its range is
#: closed at 2.0 m. Second-year and multi-year ice have no upper bound in the nomenclature
#: (inf); old ice, glacier ice and 'unknown' have no thickness (NaN).
STAGE_CODES = {
    55: ("ice free", (0.0, 0.0)),
    80: ("no stage of development", (math.nan, math.nan)),
    81: ("new ice", (0.0, 0.10)),
    82: ("nilas", (0.0, 0.10)),
    83: ("young ice", (0.10, 0.30)),
    84: ("grey ice", (0.10, 0.15)),
    85: ("grey-white ice", (0.15, 0.30)),
    86: ("first-year ice", (0.30, 2.00)),
    87: ("thin first-year ice", (0.30, 0.70)),
    88: ("thin first-year ice, stage 1", (0.30, 0.50)),
    89: ("thin first-year ice, stage 2", (0.50, 0.70)),
    91: ("medium first-year ice", (0.70, 1.20)),
    93: ("thick first-year ice", (1.20, 2.00)),
    95: ("old ice", (math.nan, math.nan)),
    96: ("second-year ice", (2.00, math.inf)),
    97: ("multi-year ice", (2.00, math.inf)),
    98: ("glacier ice", (math.nan, math.nan)),
    99: ("unknown", (math.nan, math.nan)),
}
ICE_FREE = 55
UNKNOWN_STAGE = 99

#: Special SIGRID-3 concentration codes -> (low, high) in tenths. Every other two-digit code
#: "ab" is a/10 to b/10 (a < b), or n/10 exactly for "n0".
_SPECIAL_CONCENTRATION = {0: (0.0, 0.0), 1: (0.0, 1.0), 2: (0.0, 1.0), 91: (9.0, 10.0), 92: (10.0, 10.0)}
#: How a range code becomes one number: the upper bound is the conservative default (more ice).
CONCENTRATION_RULES = ("upper", "mean", "lower")


def parse_code(value) -> float:
    """One SIGRID-3 attribute value -> its integer code as a float, or NaN when missing.

    Accepts ints, floats and text ('03', '3', ' 91 ', '3.0'); '-9', -9, '', None, NaN and
    non-numeric text (e.g. '99-9', 'X') are missing. 99 is kept: it is a code (unknown)."""
    if value is None:
        return math.nan
    if isinstance(value, (bytes, bytearray)):
        value = value.decode("ascii", "replace")
    if isinstance(value, str):
        text = value.strip()
        if not text:
            return math.nan
        try:
            number = float(text)
        except ValueError:
            return math.nan
    else:
        try:
            number = float(value)
        except (TypeError, ValueError):
            return math.nan
    if not math.isfinite(number) or number < 0 or number != int(number):
        return math.nan
    return float(number)


def parse_codes(values) -> np.ndarray:
    """`parse_code` over a sequence: float64 array, NaN where missing."""
    return np.array([parse_code(v) for v in values], dtype=float)


def concentration_range(code: float) -> tuple[float, float]:
    """(low, high) tenths of a decoded concentration code; (NaN, NaN) for missing, 99 or codes
    that are not SIGRID-3 concentrations (e.g. '75')."""
    if not math.isfinite(code):
        return (math.nan, math.nan)
    c = int(code)
    if c in _SPECIAL_CONCENTRATION:
        return _SPECIAL_CONCENTRATION[c]
    if c == 99 or not 10 <= c <= 99:
        return (math.nan, math.nan)
    a, b = divmod(c, 10)
    if b == 0:
        return (float(a), float(a))
    if a < b:
        return (float(a), float(b))
    if (a, b) == (8, 1):  # '81' is 8/10 to 10/10 in SIGRID-3
        return (8.0, 10.0)
    return (math.nan, math.nan)


def concentration_tenths(code: float, rule: str = "upper") -> float:
    """A decoded concentration code -> tenths (0-10): the `rule` end of a range code
    ('upper' by default: the most ice the analyst allowed for), NaN when unknown."""
    if rule not in CONCENTRATION_RULES:
        raise SeawayError(f"rule must be one of {CONCENTRATION_RULES}, got {rule!r}")
    lo, hi = concentration_range(code)
    return {"upper": hi, "lower": lo, "mean": (lo + hi) / 2}[rule]


def stage_name(code: float) -> str:
    """Name of a WMO stage code ('unknown' for NaN and codes outside the table)."""
    if not math.isfinite(code):
        return "unknown"
    return STAGE_CODES.get(int(code), ("unknown",))[0]


def stage_code(value) -> float:
    """A decoded stage: the WMO code if it is one of STAGE_CODES, 99 (unknown) for a number that
    is not, NaN when missing."""
    code = parse_code(value)
    if not math.isfinite(code):
        return math.nan
    return code if int(code) in STAGE_CODES else float(UNKNOWN_STAGE)


#: SIGRID-3 form of ice (FA, FB, FC; the egg code's Fa Fb Fc), JCOMM TR-23 v3.0 -> name.
FORM_CODES = {
    0: "pancake ice",
    1: "shuga, small ice cake, brash ice",
    2: "ice cake",
    3: "small floe",
    4: "medium floe",
    5: "big floe",
    6: "vast floe",
    7: "giant floe",
    8: "fast ice",
    9: "growlers, floebergs or floebits",
    10: "icebergs",
    **{10 + n: f"strips and patches, {n}/10" for n in range(1, 11)},
    21: "level ice",
    99: "undetermined or unknown",
}
FAST_ICE = 8
#: Ice of land origin among the forms (growlers, bergy bits; icebergs).
LAND_ORIGIN_FORMS = (9, 10)
#: SIGRID-3 concentration codes of freely navigable water (WMO No. 259): 01 open water (less
#: than 1/10 sea ice), 02 bergy water (less than 1/10 ice of land origin).
OPEN_WATER_CODE, BERGY_WATER_CODE = 1, 2

#: Stages from the least to the most severe: by typical thickness (upper, then lower bound),
#: old ice with the multi-year stages, then glacier ice, then unknown (99: cannot be ruled out
#: worst). `stage_rank` orders codes by it; the governing stage of a leg is the highest rank.
SEVERITY = (55, 80, 81, 82, 84, 83, 85, 88, 87, 89, 91, 86, 93, 96, 95, 97, 98, 99)
FIRST_YEAR = (86, 87, 88, 89, 91, 93)


def form_name(code: float) -> str:
    """Name of a SIGRID-3 form code ('none' for NaN; 'form <n>' for codes outside the table)."""
    if not math.isfinite(code):
        return "none"
    return FORM_CODES.get(int(code), f"form {int(code)}")


def form_code(value) -> float:
    """A decoded form: the SIGRID-3 code (0-21, 99), NaN when missing (-9, NULL, text) or out
    of the table."""
    code = parse_code(value)
    return code if math.isfinite(code) and int(code) in FORM_CODES else math.nan


def stage_rank(code: float) -> int:
    """Position of a stage code in SEVERITY (-1 for NaN or codes outside it)."""
    if not math.isfinite(code) or int(code) not in SEVERITY:
        return -1
    return SEVERITY.index(int(code))


def thickest_first_year(codes) -> float | None:
    """The most severe first-year stage (FIRST_YEAR, by SEVERITY) among `codes`, or None."""
    values = np.asarray(codes, float)
    present = [c for c in FIRST_YEAR if (values == c).any()]  # vectorised: charts are large
    return float(max(present, key=SEVERITY.index)) if present else None
