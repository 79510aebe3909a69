"""Why no route crosses an opened chart: from its ice (seaway.icenav.noroute on ice charts: the
ice that closes the way, the weakest class that gets through, how far the ship gets), else from
the chart (seaway.engine.reach), and with a draft how deep the deepest way is."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from ..engine.api import prepare
from ..engine.reach import explain_no_route as explain_chart
from ..errors import NoRouteError
from ..ice.classes import with_article
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
    probe=None,
    escorted=None,
) -> NoRouteError:
    """The NoRouteError to report for a search between `ends` (pixels or lat/lon as routed) on
    `cost` that found nothing; `asked`: the ends as given; draft: (draft, ukc) when enforced;
    blocked: what closes the pixels the cost closes beyond the class's ice, in words.
    probe: a ClassProbe (the voyage's whole model for any class: where it may go, whether it gets
    through), so the weakest class named is one that really gets through. escorted: () -> whether
    the voyage gets through under an icebreaker's escort (said when it does)."""
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
            passable=None if probe is None else probe.passable,
            gets_through=None if probe is None else (lambda c: probe.gets_through(c, ends)),
        )
    else:
        err = explain_chart(
            cost, ends[0], ends[1], land=chart.land, neighbourhood=neighbourhood, show=show, asked=asked
        )
    extra = []
    if escorted is not None and escorted():
        extra.append(
            f"with an icebreaker's escort (escort=True, --escort) {with_article(vessel or 'Arc7')} ship gets through"
        )
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


class ClassProbe:
    """The voyage's model for any ice class: the pixels it may cross (its ice table, and where the
    ship of that class has a speed of its own unless escorted; the same draft) and whether it
    finds a route between the ends (a search as the voyage's)."""

    def __init__(self, chart, price, neighbourhood=5):
        self.chart, self.price, self.neighbourhood = chart, price, neighbourhood
        self._costs: dict = {}

    def cost(self, cls):
        """The search's cost for `cls` (inf where it may not go), computed once."""
        if cls not in self._costs:
            self._costs[cls] = self.price(cls)
        return self._costs[cls]

    def passable(self, cls):
        return np.isfinite(np.asarray(self.cost(cls).values, float))

    def gets_through(self, cls, ends) -> bool:
        try:
            prepare(self.cost(cls), land=self.chart.land, neighbourhood=self.neighbourhood).route(*ends)
        except NoRouteError:
            return False
        return True
