"""Form of ice on a SIGRID-3 chart (FA, FB, FC): fast ice as an ice type of its own, and the
rules for bergy water, brash ice and icebergs. Used by seaway.ice.impact.governing_stage (and
through it chart_impact, the summaries and the command line).

Rules (FA is the form of SA's ice, the thickest; codes in seaway.ice.codes.FORM_CODES):

* **Fast ice** (FA 08) takes its stage from the chart (SA) when the chart gives one. Where it
  does not (SA 99 unknown, 80 or missing: AARI's winter charts code most of the Kara Sea so,
  FA 08 SA 99 CT 92) the stage is an ASSUMPTION, chosen with ``fast_ice=``:

  - ``"nearby"`` (the default): the thickest first-year stage (seaway.ice.codes.FIRST_YEAR,
    ordered by SEVERITY) the chart shows on the grid, in any of SA/SB/SC, fast ice or not; the
    grid the command line rasterises onto is the box around the route, so this is the ice
    near the voyage. If the grid shows no first-year stage: thick first-year ice (93). Fast ice
    grows in place from autumn, so it is at least as thick as the first-year pack around it.
  - a WMO stage code (e.g. 93 thick first-year, 91 medium first-year): that stage.
  - ``"closed"``: impassable for every class (the conservative reading of "unknown").

  The sentence saying what was assumed, on how many pixels, is returned with the stage and is
  recorded in the ``assumptions`` attribute of governing_stage's and chart_impact's results
  (and so on every Route found on them: Route.assumptions; ``seaway route`` prints it on stderr).
* **Bergy water** (CT code 02) and **open water** (CT code 01) are freely navigable water by
  definition (WMO Sea-Ice Nomenclature, WMO-No. 259: less than 1/10 of ice of land origin,
  resp. of sea ice): costed as ice free (stage 55), whatever SA says (CIS charts write SA 98
  glacier ice, FA 10 icebergs for bergy water). POLARIS agrees: less than 1/10 of any ice
  gives RIO >= 9 x 3 + 1 x (-8) = 19 > 0 for every class of MSC.1/Circ.1519 Table 1.3, i.e.
  normal operation. Recorded as a rule in ``assumptions``; icebergs may still be present.
* **Glacier ice, icebergs, growlers** (SA 98, FA 09/10) at 1/10 or more: Grinyak et al. 2022's
  tables and the Register's class limits (Table 1) give no value for ice of land origin, so
  chart_impact keeps them impassable (``unknown=`` prices them); POLARIS counts glacier ice in
  the heavy multi-year column (seaway.ice.polaris). ASSUMED, no source prices them.
* **Brash ice, floes, strips and patches** (FA 00-07, 11-21): the form does not change the
  cost; the stage (SA) governs.
"""

from __future__ import annotations

import numpy as np

from ..errors import SeawayError
from .codes import FAST_ICE, FIRST_YEAR, STAGE_CODES, UNKNOWN_STAGE, stage_name, thickest_first_year

FAST_ICE_CHOICES = ("nearby", "closed")
DEFAULT_FAST_ICE = "nearby"
DEFAULT_FAST_STAGE = 93.0  # thick first-year ice: "nearby" when the grid shows no first-year ice
#: free_water layer values (seaway.ice.sigrid): 1 open water (CT 01), 2 bergy water (CT 02).
FREE_WATER = {1: "open water", 2: "bergy water"}


def check_fast_ice(fast_ice):
    """`fast_ice` as "nearby", "closed" or a float WMO stage code; ValueError naming the choices."""
    if isinstance(fast_ice, str) and fast_ice.strip().lower() in FAST_ICE_CHOICES:
        return fast_ice.strip().lower()
    try:
        code = float(fast_ice)
    except (TypeError, ValueError):
        code = np.nan
    if np.isfinite(code) and int(code) == code and int(code) in STAGE_CODES and code not in (55, 80, 99):
        return code
    raise SeawayError(
        f"fast_ice must be 'nearby', 'closed' or a WMO stage code of ice (81-98, e.g. 93 "
        f"thick first-year ice), got {fast_ice!r}"
    )


def fast_ice_mask(ds):
    """Pixels whose form (FA) is fast ice (False everywhere when the chart has no FA layer)."""
    if "FA" not in ds:
        return np.zeros(ds["CT"].shape, bool)
    return np.asarray(ds["FA"].values) == FAST_ICE


def unknown_stage(sa):
    """Where a stage says nothing about the ice: NaN, 80 (no stage) or 99 (unknown)."""
    sa = np.asarray(sa, float)
    return np.isnan(sa) | (sa == 80) | (sa == UNKNOWN_STAGE)


FAST_HEAD = "fast ice of unknown stage (FA 08, SA 99)"
FAST_HOW = "set it with fast_ice= (API) or --fast-ice (CLI): closed, a WMO stage code, or nearby"
FREE_RULE = "freely navigable water (WMO-No. 259), costed as ice free; icebergs may be present"


def fast_ice_rule(ds, fast_ice=DEFAULT_FAST_ICE):
    """(stage code or None for closed, what is assumed in words, the pixels it applies to) for
    the fast ice of unknown stage on `ds`: the parts of fast_ice_stage's sentence (a season of
    charts says them once for all its charts, seaway.ice.seasonfast); "" when there is none."""
    rule = check_fast_ice(fast_ice)
    fast = fast_ice_mask(ds)
    land = np.asarray(ds["land"].values, bool) if "land" in ds else np.zeros(fast.shape, bool)
    where = fast & unknown_stage(ds["SA"].values) & ~land
    if not where.any():
        return None, "", where
    if rule == "closed":
        return None, "closed to every class", where
    if rule == "nearby":
        codes = [ds[s].values[~land] for s in ("SA", "SB", "SC") if s in ds]
        code = thickest_first_year(np.concatenate(codes)) if codes else None
        why = (
            "the thickest first-year stage the chart shows nearby (on the grid)"
            if code is not None
            else f"no first-year stage ({', '.join(map(str, FIRST_YEAR))}) on the grid: the "
            "thickest first-year stage"
        )
        code = DEFAULT_FAST_STAGE if code is None else code
    else:
        code, why = rule, "as you chose"
    return code, f"{stage_name(code)} (WMO {int(code)}), {why}", where


def fast_ice_stage(ds, fast_ice=DEFAULT_FAST_ICE):
    """(stage code or None for closed, the sentence saying so, the pixels it applies to) for
    the fast ice of unknown stage on `ds`; the sentence is "" when there is no such fast ice."""
    code, said, where = fast_ice_rule(ds, fast_ice)
    if not said:
        return code, "", where
    return code, f"{FAST_HEAD} on {int(where.sum())} pixels: ASSUMED {said} ({FAST_HOW})", where


def ice_words(code, fast=False, assumed=False, label="SA", guessed=False) -> str:
    """The words messages use for one pixel's ice (seaway.icenav.noroute, seaway.icenav.seasonwhy): its
    governing stage `code` (NaN: unknown, or fast ice closed by the rule) named with `label` and
    its code, ", assumed" when the whole stage layer is (`guessed`); fast ice (`fast`) is named
    so, "of unknown stage, assumed" where its stage is the fast_ice assumption (`assumed`)."""
    if not np.isfinite(code):
        return "fast ice of unknown stage, closed by the fast_ice rule" if fast else "ice of unknown stage"
    text = f"{stage_name(code)} ({label} {int(code)}{', assumed' if guessed else ''})"
    if fast:
        text = ("fast ice of unknown stage, assumed " if assumed else "fast ice, ") + text
    return text


def free_water_counts(ds):
    """(mask of open and bergy water pixels, "open water on n pixels and bergy water on m
    pixels", "" if none)."""
    if "free_water" not in ds:
        return np.zeros(ds["CT"].shape, bool), ""
    kind = np.asarray(ds["free_water"].values)
    counts = {name: int((kind == k).sum()) for k, name in FREE_WATER.items()}
    return kind > 0, " and ".join(f"{name} on {n} pixels" for name, n in counts.items() if n)


def free_water_rule(ds):
    """(mask of open and bergy water pixels, the sentence naming the rule, "" if none)."""
    free, said = free_water_counts(ds)
    return free, (f"{said} (CT 01/02): {FREE_RULE}" if said else "")
