"""The engine layer: a chart prepared once (PreparedChart), the choice of exact method, the typed
search result and the one path from it to a Route; via points, turn penalties and the least-danger
route on top; ends moved into water that joins them (snap) and why no route exists (reach)."""

from .api import cost_field, prepare, route
from .methods import METHODS
from .prepared import PreparedChart
from .reach import explain_no_route
from .snap import SnapError, SnappedEnds, snap_ends

__all__ = [
    "PreparedChart",
    "prepare",
    "route",
    "cost_field",
    "METHODS",
    "snap_ends",
    "SnappedEnds",
    "SnapError",
    "explain_no_route",
]
