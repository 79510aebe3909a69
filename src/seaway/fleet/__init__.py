"""Many routes in one call (route_many): voyages x vessels x charts, in threads or on a Dask
cluster."""

from .many import COLUMNS, route_many

__all__ = ["route_many", "COLUMNS"]
