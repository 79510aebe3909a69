"""Fast ice, open and bergy water in a season of ice charts: the static path's rules
(seaway.ice.forms) applied chart by chart, and said once for the whole season.

A season read from SIGRID-3 files (seaway.icenav.season.read_season) keeps each chart's form of ice
(FA, FB, FC), its second and third stages (SB, SC: the "nearby" rule reads them) and its
`free_water` layer (CT 01 open water, 02 bergy water). Every chart then follows
seaway.ice.forms exactly as a single chart does:

* fast ice (FA 08) takes its stage from the chart (SA) where it gives one; where it does not
  (AARI's winter charts: FA 08, SA 99, CT 92) the stage is the ``fast_ice`` assumption, decided
  chart by chart: "nearby" (default: the thickest first-year stage that chart shows on the
  grid, else thick first-year 93), a WMO stage code, or "closed" (impassable for every class);
* open and bergy water (CT 01/02) are freely navigable, costed as ice free; glacier ice and
  icebergs at 1/10 or more stay closed; brash ice and floes: the stage governs.

The rule is the ``fast_ice=`` of IceSeasonTime, route_season and arrival_field, else the one
read_season recorded on the season (its attribute ``fast_ice``), else "nearby".
season_assumptions says in one sentence per rule which charts it applied to and on how many
pixels; IceSeasonTime puts them on every route (Route.assumptions, hence the GeoJSON property
``assumptions``, the route's table and ``seaway season``'s stderr).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np

from .forms import (
    DEFAULT_FAST_ICE,
    FAST_HEAD,
    FAST_HOW,
    FREE_RULE,
    check_fast_ice,
    fast_ice_mask,
    fast_ice_rule,
    free_water_counts,
    ice_words,
)
from .impact import governing_stage

if TYPE_CHECKING:
    import xarray as xr

#: The layers of a SIGRID-3 chart (seaway.ice.sigrid.read_sigrid3) a season keeps, when present.
SEASON_LAYERS = ("CT", "CA", "SA", "SB", "SC", "FA", "FB", "FC", "free_water", "land", "off_chart")

__all__ = ["SEASON_LAYERS", "season_layers", "season_rule", "record_rule", "season_assumptions", "describer"]


def season_layers(chart) -> list[str]:
    """The names of SEASON_LAYERS that `chart` (one read_sigrid3 Dataset) has."""
    return [name for name in SEASON_LAYERS if name in chart]


def season_rule(ds: xr.Dataset, fast_ice: str | float | None = None) -> str | float:
    """The fast-ice rule for a season (or one of its charts): `fast_ice` when given, else the
    rule recorded on it (``ds.attrs["fast_ice"]``, read_season's), else "nearby"; checked
    (seaway.ice.forms.check_fast_ice: "nearby", "closed" or a WMO stage code as a float)."""
    if fast_ice is None:
        fast_ice = ds.attrs.get("fast_ice", DEFAULT_FAST_ICE)
    return check_fast_ice(fast_ice)


def record_rule(ds, fast_ice):
    """`ds` with the fast-ice rule recorded as its attribute ``fast_ice`` (None: as it is)."""
    if fast_ice is not None:
        ds.attrs["fast_ice"] = season_rule(ds, fast_ice)
    return ds


def _date(t) -> str:
    text = np.datetime_as_string(np.datetime64(t, "m"))
    return text[:10] if text.endswith("T00:00") else text


def _charts(items) -> str:
    """ "the chart of D (n pixels)" or "the charts of D1 (n1 pixels), D2 (...) and D3 (...)"."""
    each = [f"{_date(t)} ({said})" for t, said in items]
    if len(each) == 1:
        return f"the chart of {each[0]}"
    return f"the charts of {', '.join(each[:-1])} and {each[-1]}"


def season_assumptions(
    ds: xr.Dataset, first: int = 0, fast_ice: str | float | None = None
) -> tuple[str, ...]:
    """What the season's charts from index `first` on assume, one sentence per kind: fast ice of
    unknown stage (the stage per chart under the rule, the charts and pixels it applied to),
    then open and bergy water (seaway.ice.forms.FREE_RULE); () when neither is on any chart."""
    rule = season_rule(ds, fast_ice)
    fast: dict[str, list] = {}
    free = []
    for k in range(first, ds.sizes["time"]):
        frame = ds.isel(time=k)
        t = ds["time"].values[k]
        if "SA" in frame and "FA" in frame:
            _, said, where = fast_ice_rule(frame, rule)
            if said:
                fast.setdefault(said, []).append((t, f"{int(where.sum())} pixels"))
        counts = free_water_counts(frame)[1]
        if counts:
            free.append((t, counts))
    out = []
    if fast:
        parts = "; ".join(f"in {_charts(items)}: ASSUMED {said}" for said, items in fast.items())
        out.append(f"{FAST_HEAD} {parts} ({FAST_HOW})")
    if free:
        out.append(f"open or bergy water (CT 01/02) in {_charts(free)}: {FREE_RULE}")
    return tuple(out)


def describer(ds: xr.Dataset, fast_ice: str | float | None = None) -> Callable[..., str]:
    """(row, col[, concentration]) -> the ice of that pixel of one chart of a season in words:
    its governing stage under the fast-ice rule, fast ice named as seaway.icenav.noroute names it
    (seaway.ice.forms.ice_words), or its thickness; and its total concentration."""
    ct = np.round(np.asarray(ds["CT"].values, float), 1)  # a model's 6.48207/10 reads 6.5/10
    stage = None
    if "SA" in ds:
        rule = season_rule(ds, fast_ice)
        stage = np.asarray(governing_stage(ds, fast_ice=rule).values, float)
        fast, assumed = fast_ice_mask(ds), fast_ice_rule(ds, rule)[2]
    thick = np.asarray(ds["thickness"].values, float) if "thickness" in ds else None

    def ice(r, c, concentration=True) -> str:
        text = "ice"
        if stage is not None:
            text = ice_words(stage[r, c], bool(fast[r, c]), bool(assumed[r, c]))
        elif thick is not None:
            text = f"ice {thick[r, c]:.1f} m thick"  # to 0.1 m: kinds, not every pixel
        if not concentration:
            return text
        return text + (f" at {ct[r, c]:g}/10" if np.isfinite(ct[r, c]) else ", concentration unknown")

    return ice
