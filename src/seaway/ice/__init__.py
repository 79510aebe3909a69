"""Ice navigation: ice classes, SIGRID-3 codes, and the cost models of Grinyak et al. 2022 (impact
tables), IMO POLARIS (MSC.1/Circ.1519) and Andreeva 2021 (Andreeva: speed V = F*V0, time, Pareto).

Modules: classes, codes, impact, polaris, andreeva (formulas), colours; pareto (Andreeva's
time-safety routes), summary, season (routes through a time series of charts; numpy/xarray
only; seasonwhy: its ends and why no route gets through it) and sigrid
(readers of SIGRID-3 shapefiles/GeoPackages and NSIDC NetCDF; needs ``pip install
"seaway[ice]"``, imported only when you import seaway.ice.sigrid).

Ice chart Dataset (what seaway.ice.sigrid returns; models accept any Dataset with these names):

======== ============ ===================================================================
name     units        meaning
======== ============ ===================================================================
CT       tenths (0.1) total concentration, 0-10 (range codes -> upper end by default);
                      NaN = unknown or off the chart
CA CB CC tenths (0.1) partial concentrations of SA, SB, SC
SA SB SC WMO code     stage of development, thickest first (55 ice free, 81-98; 99 unknown;
                      NaN = no such ice)
land     bool         land (POLY_TYPE L) or ice shelf (S): impassable
ice_shelf bool        ice-shelf polygons (POLY_TYPE S)
off_chart bool        no polygon covers the pixel centre (all layers NaN)
polygon  index        row of the source file's polygon at the pixel (-1 none)
thickness m           sea-ice thickness (gridded products; optional)
depth    m            water depth, positive down (optional; Andreeva 2021's Z)
======== ============ ===================================================================
Coordinates: lat/lon (degrees, pixel centres) or y/x (km in the grid's projection, whose
PROJ string is the Dataset attribute ``crs``).
"""

import importlib

from . import andreeva, classes, codes, impact, polaris
from .classes import CLASSES, IceClass, class_names, get_class
from .impact import ICE_IMPACT, chart_impact, ice_impact

#: The modules that route (they import the engine, which imports the formulas above): loaded on
#: first use, so that the cost models can read the ice classes without a cycle.
_ROUTING = ("pareto", "season", "seasonwhy", "summary", "noroute")


def __getattr__(name):
    if name in _ROUTING:
        return importlib.import_module(f"{__name__}.{name}")
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = [
    "andreeva",
    "classes",
    "codes",
    "impact",
    "polaris",
    "pareto",
    "season",
    "seasonwhy",
    "summary",
    "noroute",
    "CLASSES",
    "IceClass",
    "class_names",
    "get_class",
    "ICE_IMPACT",
    "ice_impact",
    "chart_impact",
]
