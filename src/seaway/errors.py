"""Exceptions raised by seaway."""

from __future__ import annotations

from collections.abc import Iterable


class NoRouteError(ValueError):
    """The end cannot be reached from the start on this chart and stencil.

    A search that fails raises it with its message only. The explanations add what the chart
    says about why (seaway.engine.reach.explain_no_route for any chart,
    seaway.icenav.noroute.explain_no_route for ice charts; ``seaway route`` always asks them), as
    attributes (None or empty when not known):

    cause: "land" (the ends lie in separate bodies of water even with every impassable pixel
        that is not land opened: the land mask, or the stencil, keeps them apart), "ice" (ice
        the vessel may not enter closes the way) or "impassable" (pixels of infinite or NaN
        cost that are not land close it).
    closing_ice: ((description, km), ...): the ice that closes the way, most first (stage,
        concentration and form: "first-year ice (SA 86) at 10/10", "fast ice, ..."), with the
        km of it on the way that crosses the least of it.
    weakest_class: the weakest class of seaway.ice.classes that gets through ("Arc7"), or
        None when none does (see cause and closing_ice).
    reachable: the point the ship can reach that is nearest the end, (lat, lon) (on a planar
        chart its (y, x)); reachable_km: its distance to the end (km; chart units on planar
        charts).
    """

    def __init__(
        self,
        message: str = "",
        *,
        cause: str | None = None,
        closing_ice: Iterable[tuple[str, float]] = (),
        weakest_class: str | None = None,
        reachable: tuple[float, ...] | None = None,
        reachable_km: float | None = None,
    ) -> None:
        super().__init__(message)
        self.cause, self.closing_ice, self.weakest_class = cause, tuple(closing_ice), weakest_class
        self.reachable, self.reachable_km = reachable, reachable_km
