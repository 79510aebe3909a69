"""Ice navigation: ice classes, SIGRID-3 codes, and the cost models of Grinyak et al. 2022 (impact
tables), IMO POLARIS (MSC.1/Circ.1519) and Andreeva 2021 (Andreeva: speed V = F*V0, time, Pareto).

The ice knowledge the rest of the package rests on. Modules: classes, codes, forms (fast ice,
open and bergy water), impact, polaris, andreeva (formulas), speed (a class's speed in a chart's
ice), colours; seasongrid (a season of charts on one grid and a class's hours per km in each),
seasonspeed and seasonfast (a chart of a season); concentration (a concentration-only chart as
an ice chart); sigrid, geometry, grids, routegrid, vectorfile (readers of SIGRID-3
shapefiles/GeoPackages and NSIDC NetCDF onto a grid; they need ``pip install "seaway[ice]"``).
Routing through the ice (seasons, why no route, Pareto routes, summaries) is seaway.icenav.

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

from . import andreeva, classes, codes, impact, polaris
from .classes import CLASSES, IceClass, class_names, get_class
from .codes import stage_name
from .concentration import concentration_chart
from .forms import check_fast_ice
from .impact import ICE_IMPACT, chart_impact, governing_stage, ice_impact
from .polaris import polaris_chart
from .seasongrid import SeasonGrid, as_season, read_season
from .sigrid import read_sigrid3
from .speed import ice_speed

__all__ = [
    "andreeva",
    "classes",
    "codes",
    "impact",
    "polaris",
    "CLASSES",
    "IceClass",
    "class_names",
    "get_class",
    "ICE_IMPACT",
    "ice_impact",
    "chart_impact",
    "governing_stage",
    "stage_name",
    "check_fast_ice",
    "ice_speed",
    "polaris_chart",
    "concentration_chart",
    "read_sigrid3",
    "SeasonGrid",
    "as_season",
    "read_season",
]
