"""Water depth and draft: bathymetry files in (NetCDF, GeoTIFF; depth or elevation, sign and
units found from the file), resampled onto a chart's grid (lat/lon or projected), pixels too
shallow for draft + under-keel clearance closed, the least depth along a route and the deepest
way between two points."""

from .bathymetry import Bathymetry, open_bathymetry
from .draft import (
    DEFAULT_UKC_SHARE,
    apply_draft,
    check_draft,
    deepest_way,
    depth_on_grid,
    least_depth,
    too_shallow,
)

__all__ = [
    "Bathymetry",
    "open_bathymetry",
    "DEFAULT_UKC_SHARE",
    "apply_draft",
    "check_draft",
    "deepest_way",
    "depth_on_grid",
    "least_depth",
    "too_shallow",
]
