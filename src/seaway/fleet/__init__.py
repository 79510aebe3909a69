"""Many routes in one call: route_many (static charts: voyages x vessels x charts, in threads or
on a Dask cluster) and route_voyages (vessels x voyages x departures through an opened chart,
season or forecast, waits for the ice included); od_matrix (hours between ports through a
season or across one ice chart, or the cost on a prepared chart: one search per origin);
local_cluster (a Client on a LocalCluster of its own, shut down without tracebacks)."""

from .many import COLUMNS, route_many
from .matrix import od_matrix
from .run import local_cluster
from .voyages import daily, route_voyages, to_dataset

__all__ = ["route_many", "COLUMNS", "route_voyages", "daily", "to_dataset", "od_matrix", "local_cluster"]
