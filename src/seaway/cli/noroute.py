"""What `seaway route` says when no route is found: why, from the chart (seaway.icenav.noroute on
ice charts: the ice that closes the way, the weakest class that gets through, how far the ship
gets; seaway.engine.reach on other charts), and with --depth how deep the deepest way is."""

from __future__ import annotations

from ..engine.reach import explain_no_route as explain_chart
from ..errors import NoRouteError
from ..icenav.noroute import explain_no_route as explain_ice
from .depth import why_no_route as why_depth
from .projected import pixel_latlon


def ice_chart(data, args) -> bool:
    """Is the route's cost the ice of the chart (stages for a class), not a cost variable?"""
    layers = data.layers
    return bool(
        layers is not None and ("SA" in layers or "stage_of_development" in layers) and not args.variable
    )


def why_no_route(data, cost, ends, args, *, depth=None, shallow=None, constrained=False) -> NoRouteError:
    asked = (args.start, args.end)
    """The NoRouteError to report for a search between `ends` on `cost` that found nothing."""
    layers = data.layers
    show = pixel_latlon(cost, data.projection)
    if ice_chart(data, args):
        blocked = (
            "water shallower than draft + UKC"
            if shallow is not None
            else "closed by the cost, not by the ice"
        )
        err = explain_ice(
            layers,
            args.vessel or "Arc7",
            ends[0],
            ends[1],
            cost=cost,
            neighbourhood=args.neighbourhood,
            fast_ice=args.fast_ice,
            blocked_name=blocked,
            show=show,
            asked=asked,
        )
    else:
        err = explain_chart(
            cost, ends[0], ends[1], land=data.land, neighbourhood=args.neighbourhood, show=show, asked=asked
        )
    extra = []
    if shallow is not None:
        extra.append(why_depth(data.cost, data.land, depth, ends[0], ends[1], args.draft, args.ukc))
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
