"""The raster a voyage on one opened chart is searched on: the vessel and its class, the class's
cost, the draft's shallows closed, the ship's speed in the ice (seaway.voyage.timing) and the
true-km scale of a projected grid. Written once here for OpenChart.route (seaway.voyage.route)
and the isochrones of OpenChart.arrival_field / hours_per_km (seaway.voyage.chartfield), so a
field and a route price a voyage alike."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from ..errors import SeawayError
from ..ice.classes import get_class
from .depth import with_draft
from .projected import true_cost
from .ship import as_vessel, vessel_notes
from .timing import end_reasons, ice_time, over_limit, search_cost, time_notes

if TYPE_CHECKING:
    import xarray as xr

    from ..vessel import Vessel
    from .chart import OpenChart


@dataclass
class Pricing:
    """What price_chart found, for the search and for the words about it."""

    ship: Vessel | None  # the vessel routed (a ship of the chart's class on an ice chart)
    cls: str | None  # its ice class on an ice chart
    draft: float | None  # the draft enforced (None: none, or the chart has no depth)
    ukc: float | None
    chart_cost: xr.DataArray  # the class's cost, before the draft and the concentration limit
    cost: xr.DataArray  # with pixels too shallow for the draft closed
    shallow: Any  # with_draft's reasons for a too-shallow end, or None
    timing: Any  # seaway.voyage.timing.IceTime on an ice chart, else None
    routed: xr.DataArray  # what the search prices, per true km
    reasons: Any  # (row, col) -> why an end is closed beyond the class's ice (timing.end_reasons)
    notes: list[str] = field(default_factory=list)  # the vessel, the draft, the times in the ice


def price_chart(
    chart: OpenChart,
    *,
    vessel: Vessel | str | None = None,
    speed_kn: float | None = None,
    objective: str = "impact",
    edge_cost: str = "max",
    escort: bool = False,
    escort_speed_kn: float | None = None,
    stage_thickness: Any = None,
    draft_m: float | None = None,
    ukc_m: float | None = None,
    concentration_limit: bool = False,
    say: Callable[[str], None] | None = None,
) -> Pricing:
    """The search's raster on `chart` for this vessel and objective ("impact" or "time"), with
    what it assumed in `notes` (OpenChart.route's options of the same names)."""
    given = vessel if vessel is not None else chart.vessel
    ship = as_vessel(given, speed_kn, ukc_m=ukc_m)
    cls = chart.ice_class(ship.ice_class if ship is not None else None)
    if chart.is_ice and (ship is None or ship.ice_class is None):
        ship = as_vessel(cls, ship.speed_kn if ship is not None else speed_kn, ukc_m=ukc_m)
    notes = vessel_notes(ship) if chart.is_ice or ship is not None and ship.path else []
    chart_cost = chart.cost_for(cls)
    over = over_limit(chart, cls) if concentration_limit and cls is not None else None
    if concentration_limit and cls is not None:
        limit = get_class(cls).max_concentration
        notes.append(
            f"ice over {cls}'s concentration limit for independent navigation ({limit:g}/10 total "
            "concentration, Grinyak et al. 2022 Table 1) is closed (concentration_limit)"
        )
    draft = draft_m if draft_m is not None else (ship.draft_m if ship is not None else None)
    if draft is not None and draft_m is None and chart.depth is None:
        notes.append(
            f"the draft {draft:g} m is not enforced: the chart has no depth (open it with depth=FILE)"
        )
        draft = None
    ukc = ukc_m if ukc_m is not None else (ship.ukc_m if ship is not None and draft is not None else None)
    limited = chart.cost_for(cls, concentration_limit=concentration_limit)
    cost, shallow = with_draft(limited, chart.depth, draft, ukc, say)
    timing = priced = None
    if chart.is_ice and chart.layers is not None:
        timing = ice_time(
            chart,
            cls,
            ship,
            cost,
            escort=escort,
            escort_kn=escort_speed_kn,
            stage_thickness=stage_thickness,
            draft_m=draft,
        )
        priced = search_cost(cost, timing, objective)
        notes += time_notes(timing, objective, edge_cost)
    elif objective == "time":
        raise SeawayError(
            "objective time needs an ice chart (a speed in its ice); this chart is a cost raster"
        )
    routed = true_cost(chart.projection, cost if priced is None else priced)  # per true km
    reasons = end_reasons(shallow, timing, over)
    return Pricing(ship, cls, draft, ukc, chart_cost, cost, shallow, timing, routed, reasons, notes)
