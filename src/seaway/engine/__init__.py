"""The engine layer: a chart prepared once (PreparedChart), the choice of exact method, the typed
search result and the one path from it to a Route; via points, turn penalties and the least-danger
route on top."""

from .api import cost_field, prepare, route
from .methods import METHODS
from .prepared import PreparedChart

__all__ = ["PreparedChart", "prepare", "route", "cost_field", "METHODS"]
