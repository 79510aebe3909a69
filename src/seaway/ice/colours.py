"""The WMO colour code for sea-ice charts, for maps (seaway.plot, seaway.output.webmap).

Source: JCOMM Technical Report No. 24, WMO/TD-No. 1215, "Ice Chart Colour Code Standard"
(version 1.0, 2014; approved by the JCOMM Expert Team on Sea Ice in October 2002; an extension
of the WMO Sea-Ice Nomenclature, WMO-No. 259). It defines two mutually exclusive codes, one per
chart: by total concentration (CT, for charts whose stage of development is fairly uniform,
e.g. Arctic summer) and by stage of development (SoD, for charts of high, fairly uniform
concentration, e.g. Arctic winter). Stage codes are SIGRID-3's (seaway.ice.codes).

Checked (2026-12): the concentration RGB values of ice free 0-100-255, < 1/10
150-200-255, 1-3/10 140-255-160 and 4-6/10 255-255-0 against the approved proposal's colour
table (J. Falkingham for the IICWG colour sub-group, "Ice Chart Colour Standard", JCOMM ETSI,
October 2002); the class names and colours (orange 7-8/10, red 9-10/10, grey fast ice) against
Environment Canada's "Interpreting ice charts", chapter 2. The 7-8/10 value 255-125-7 and the
stage-of-development RGB values below are the standard's as recalled, NOT yet checked against
the TR-24 table itself (it was not reachable from here).

Fast ice is grey in both codes (Environment Canada, chapter 2: "Grey: fast ice"; 150-150-150 in
the IICWG proposal, J. Falkingham 2001): `classes(..., fast=mask)` draws the pixels whose form of
ice is fast ice (SIGRID-3 FA 08) so, over their stage or concentration colour. Land on the maps
is therefore not grey (seaway.output.style.LAND_COLOUR).
"""

from __future__ import annotations

import numpy as np

from ..errors import SeawayError
from .codes import STAGE_CODES

#: Total concentration classes: (label, lower bound in tenths (inclusive), RGB). A value
#: belongs to the last class whose bound it reaches; exactly 0 is "ice free".
CONCENTRATION = (
    ("ice free", 0.0, (0, 100, 255)),
    ("< 1/10 (open water)", 0.0, (150, 200, 255)),  # 0 < CT < 1
    ("1-3/10 (very open drift ice)", 1.0, (140, 255, 160)),
    ("4-6/10 (open drift ice)", 4.0, (255, 255, 0)),
    ("7-8/10 (close drift ice)", 7.0, (255, 125, 7)),
    ("9-10/10 (very close drift ice)", 9.0, (255, 0, 0)),
)

#: Stage of development: SIGRID-3 code -> RGB. Codes 80 (no stage), 98 (glacier ice) and
#: 99 (unknown) have no colour in the standard: they are drawn as undefined ice.
STAGE_RGB = {
    55: (0, 100, 255),  # ice free
    81: (240, 210, 250),  # new ice
    82: (255, 135, 255),  # nilas, ice rind
    83: (170, 40, 240),  # young ice
    84: (135, 60, 215),  # grey ice
    85: (220, 80, 235),  # grey-white ice
    86: (255, 255, 0),  # first-year ice
    87: (155, 210, 0),  # thin first-year ice
    88: (215, 250, 130),  # thin first-year ice, first stage
    89: (175, 250, 0),  # thin first-year ice, second stage
    91: (0, 200, 20),  # medium first-year ice
    93: (0, 120, 0),  # thick first-year ice
    95: (180, 100, 50),  # old ice
    96: (255, 120, 10),  # second-year ice
    97: (200, 0, 0),  # multi-year ice
}
UNDEFINED = ("undefined ice", (255, 255, 255))
FAST_ICE = ("fast ice", (150, 150, 150))


def tenths(concentration) -> np.ndarray:
    """Concentration in tenths from tenths (max <= 10), percent (max > 10) or a fraction
    (max <= 1) as found in the values; NaN stays NaN."""
    c = np.asarray(concentration, float)
    top = np.nanmax(c) if np.isfinite(c).any() else 0.0
    if top <= 1.0:
        return c * 10.0
    if top > 10.0:
        return c / 10.0
    return c


def classes(ice, code: str, fast=None):
    """Classify an ice raster for a map: (index array with -1 where there is no value,
    [(label, (r, g, b)), ...] of the classes the index refers to).

    code: "concentration" (values in tenths, percent or a fraction) or "stage" (SIGRID-3
    stage-of-development codes). fast: optional mask of fast ice (form FA 08), drawn as fast
    ice whatever its stage or concentration."""
    index, table = _classes(np.asarray(ice, float), code)
    if fast is not None and np.asarray(fast, bool).any():
        index[np.asarray(fast, bool)] = len(table)
        table.append(FAST_ICE)
    return index, table


def _classes(values, code):
    index = np.full(values.shape, -1, np.int16)
    if code == "concentration":
        t = tenths(values)
        table = [(label, rgb) for label, _, rgb in CONCENTRATION]
        for k, (_, low, _) in enumerate(CONCENTRATION[1:], start=1):
            index[np.isfinite(t) & (t > 0) & (t >= low)] = k
        index[t == 0] = 0
        return index, table
    if code == "stage":
        table = []
        for k, stage in enumerate(sorted(STAGE_RGB)):
            table.append((STAGE_CODES[stage][0], STAGE_RGB[stage]))
            index[values == stage] = k
        undefined = np.isfinite(values) & (index < 0)
        if undefined.any():
            index[undefined] = len(table)
            table.append(UNDEFINED)
        return index, table
    raise SeawayError(f"code must be 'concentration' or 'stage', got {code!r}")


def guess_code(ice) -> str:
    """'stage' when every value is a SIGRID-3 stage code (55, 80-99), else 'concentration'."""
    v = np.asarray(ice, float)
    v = v[np.isfinite(v)]
    if v.size and np.isin(v, list(STAGE_CODES)).all() and (v >= 55).all():
        return "stage"
    return "concentration"
