"""Why no route crosses an opened chart: from its ice (seaway.icenav.noroute on ice charts: the
ice that closes the way, the weakest class that gets through, how far the ship gets), else from
the chart (seaway.engine.reach), and with a draft how deep the deepest way is."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..engine.reach import explain_no_route as explain_chart
from ..errors import NoRouteError
from ..icenav.noroute import explain_no_route as explain_ice
from .depth import why_no_route as why_depth
from .projected import pixel_latlon

if TYPE_CHECKING:
    from .chart import OpenChart


def why_no_route(
    chart: OpenChart,
    cost,
    ends,
    asked,
    *,
    vessel=None,
    neighbourhood=5,
    depth=None,
    draft=None,
    constrained=False,
    blocked=None,
) -> NoRouteError:
    """The NoRouteError to report for a search between `ends` (pixels or lat/lon as routed) on
    `cost` that found nothing; `asked`: the ends as given; draft: (draft, ukc) when enforced;
    blocked: what closes the pixels the cost closes beyond the class's ice, in words."""
    show = pixel_latlon(cost, chart.projection)
    if chart.is_ice and chart.layers is not None:
        blocked = blocked or "closed by the cost, not by the ice"
        err = explain_ice(
            chart.layers,
            vessel or "Arc7",
            ends[0],
            ends[1],
            cost=cost,
            neighbourhood=neighbourhood,
            fast_ice=chart.options.fast_ice,
            blocked_name=blocked,
            show=show,
            asked=asked,
        )
    else:
        err = explain_chart(
            cost, ends[0], ends[1], land=chart.land, neighbourhood=neighbourhood, show=show, asked=asked
        )
    extra = []
    if draft is not None:
        extra.append(why_depth(chart.cost_for(vessel), chart.land, depth, ends[0], ends[1], *draft))
    if constrained:
        extra.append(
            "(the explanation counts the chart's land, ice and depth, not the "
            "constraints --keep-away/--zone/--via/--turn-penalty, which may close the way too)"
        )
    if not extra:
        return err
    return NoRouteError(
        "; ".join([str(err)] + extra),
        cause=err.cause,
        closing_ice=err.closing_ice,
        weakest_class=err.weakest_class,
        reachable=err.reachable,
        reachable_km=err.reachable_km,
    )
