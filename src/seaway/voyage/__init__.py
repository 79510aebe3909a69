"""From a file to a voyage in one call: what the command line does, as a library.

``seaway.open_chart(path, ...)`` opens every chart file ``seaway route`` opens (NetCDF, GeoTIFF,
SIGRID-3, NSIDC, ROMS, the built-in "kara") with its land, CRS, fast-ice rule, assumed stage and
grid, and returns an OpenChart that routes: ``chart.route(start, end, vessel=..., ...)`` gives the
Route the command line prints and writes. The command line (seaway.cli) parses its arguments,
calls these and prints."""

from __future__ import annotations

import os
from typing import Any

from ..errors import ChartError
from .chart import ChartOptions, OpenChart
from .chartfile import read_chart
from .coast import GLOBE_KM, MERGE_MAX_KM, PACKAGE_COAST, geographic, merge_coast, pixel_km
from .depth import read_depth
from .forecast import OpenForecast, open_forecast
from .season import OpenSeason, open_season

__all__ = [
    "open_chart",
    "OpenChart",
    "ChartOptions",
    "open_season",
    "OpenSeason",
    "open_forecast",
    "OpenForecast",
]


def open_chart(
    path: str | os.PathLike[str],
    *,
    vessel: str | None = None,
    ends: tuple[tuple[float, float], tuple[float, float]] | None = None,
    options: ChartOptions | None = None,
    **option_values: Any,
) -> OpenChart:
    """Open a chart file for routing.

    path: a NetCDF chart (a cost variable, a stage of development, a sea-ice concentration such as
        NSIDC's, an ocean model's ice), a GeoTIFF cost raster, a SIGRID-3 chart (.shp, .gpkg;
        the [ice] extra), or "kara" (the built-in synthetic winter Kara Sea).
    vessel: the ice class its ice is priced for by default (Arc7 on stage charts; a
        concentration chart needs one, here or in route()).
    ends: ((lat, lon), (lat, lon)) of the voyage: a SIGRID-3 chart is then rasterised onto the
        box around them (seaway.ice.routegrid), as ``seaway route`` does, unless `grid` is given.
    options, option_values: a ChartOptions, or its fields as keywords (variable, land_variable,
        grid, fast_ice, assume_stage, depth, depth_variable, depth_positive).

    What was read and assumed is in `.notes` (and every route's notes); ChartError names what
    cannot be used and the fix."""
    if options is None:
        try:
            options = ChartOptions(**option_values)
        except TypeError as exc:
            raise ChartError(
                f"open_chart: {exc}; the options are {', '.join(ChartOptions.__annotations__)}"
            ) from None
        except ValueError as exc:
            raise ChartError(str(exc)) from None
    elif option_values:
        raise ChartError(
            "give the chart's options either as options=ChartOptions(...) or as keywords, not both"
        )
    chart = read_chart(path, options, vessel, ends)
    if options.land != "chart" and geographic(chart) and min(chart.grid.shape) > 1:
        px = pixel_km(chart)
        if options.land is None and px <= 1.5 * GLOBE_KM:
            chart.notes.append(f"land: the chart's own ({px:.2f} km pixels, as fine as {PACKAGE_COAST})")
        elif options.land is None and px > MERGE_MAX_KM:
            chart.notes.append(
                f"land: the chart's own, on {px:.0f} km pixels: a route may cross land finer than that (not merged: "
                f"{PACKAGE_COAST} on such pixels would close straits narrower than {2 * px:.0f} km); --land FILE "
                "merges a finer land mask or coast polygons, --grid routes a finer grid"
            )
        else:
            merge_coast(chart, options.land)
    if options.depth is not None:
        crs = getattr(chart.layers, "attrs", {}).get("crs")
        chart.depth, said = read_depth(
            options.depth,
            chart.grid,
            variable=options.depth_variable,
            positive=options.depth_positive,
            crs=crs,
        )
        chart.notes += said
    return chart
