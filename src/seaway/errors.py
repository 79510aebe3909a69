"""The errors seaway raises on bad input or when no route exists: one base, SeawayError (a
ValueError, so handlers of ValueError still catch it), and a subclass per kind. All are
importable from ``seaway``."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any


class SeawayError(ValueError):
    """Input seaway cannot use, or a question without an answer; the message names the cause
    and the fix. Every error the package raises on bad input is one."""


class SeawayTypeError(SeawayError, TypeError):
    """An argument of the wrong type (also a TypeError)."""


class ChartError(SeawayError):
    """A chart (a file, a raster, its grid or land) that cannot be read or used."""


class ForecastError(SeawayError):
    """A forecast file, or a role of it, that cannot be read or used."""


class VesselFileError(SeawayError):
    """A vessel file that cannot be used; the message names the file, the field and the fix."""


class SnapError(SeawayError):
    """An end is impassable and the nearest usable point joined to the other end is farther
    than the limit. `moves`: the Move of each such end (seaway.engine.snap); `limit`: the
    largest move allowed; `unit`: "km" (geographic charts) or "chart units"."""

    def __init__(self, moves: Iterable[Any], limit: float, unit: str, message: str | None = None) -> None:
        self.moves, self.limit, self.unit = tuple(moves), float(limit), unit
        far = "; ".join(m.sentence(unit) for m in self.moves)
        super().__init__(
            message
            or f"{far}: farther than max_km={self.limit:g}; give ends in water the ship can use, or a larger max_km"
        )


class NoRouteError(SeawayError):
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
        notes: Iterable[str] = (),
    ) -> None:
        super().__init__(message)
        #: What the voyage assumed or changed before the search (an end moved, the fast-ice
        #: rule), in words: the command line says them before the error.
        self.notes = tuple(notes)
        self.cause, self.closing_ice, self.weakest_class = cause, tuple(closing_ice), weakest_class
        self.reachable, self.reachable_km = reachable, reachable_km
