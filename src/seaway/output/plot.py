"""PNG maps of a route over its chart, and of an accumulated-cost field (matplotlib and cartopy,
an optional extra: pip install "seaway[plot]").

Geographic charts are drawn as ice services draw ice charts: on a polar stereographic map
(north or south by the chart's mean latitude) with a graticule and a coastline, ice in the WMO
colour code (seaway.ice.colours: by total concentration or by stage of development) with a
legend, and the route in ROUTE_COLOUR with its waypoints and ends. The coastline never comes from
the network (cartopy's Natural Earth download): land is the chart's own land mask, and around
it the 1-km global land mask that the global-land-mask package ships. Planar (y/x) charts are
drawn on plain axes. A raster without an ice code (a cost, a cost field) keeps its colour bar.
A route found through a forecast is drawn on the weather it meets at departure, its ice chart's
ice and the pixels no chart polygon covers (off chart, not land): seaway.output.voyagemap."""

from __future__ import annotations

import numpy as np

from ..base.files import write_all
from ..base.units import KM_PER_NM
from ..chart.raster import as_chart
from ..errors import SeawayError
from ..ice.colours import classes
from ..result.environment import least_depth
from .mapframe import MapFrame
from .style import COAST_COLOUR, LAND_COLOUR, SHOAL_COLOUR, fast_ice, ice_layer, point_xy, shoals
from .voyagemap import OFF_CHART_COLOUR, OFF_CHART_LABEL, WEATHER_CMAP, voyage_layers


def plot_route(route, path, **options) -> None:
    """Write a PNG map of the route over its chart (route_png(route, **options)), atomically."""
    write_all([(path, route_png(route, **options))])


def route_png(
    route,
    *,
    ice=None,
    code=None,
    values=None,
    label=None,
    title=None,
    size=None,
    dpi=100,
    cmap="Blues",
    shoal_m=None,
) -> bytes:
    """A PNG map of the route over its chart, as bytes.

    ice: a raster on the chart's grid to draw in the WMO colour code (SIGRID-3 stage codes or
        concentration in tenths, percent or a fraction); default: the route's environment
        (stage_of_development/SA, else sea_ice_concentration/CT), if any.
    code: "stage" or "concentration" (default: guessed from the values).
    values: any other raster to draw instead, with a colour bar (`label` names it); with no ice
        and no values, the cost raster is drawn.
    size: (width, height) in inches (pixels = size x dpi); default 11 inches wide, as high as the
        map's aspect needs.
    shoal_m: with a depth environment (Route.with_environment({"depth": ...})), water shallower
        than this (draft + UKC) is drawn as shoal; the route's least depth is marked either way.
    Fast ice (an FA environment, form 08) is drawn as fast ice. A weather voyage (a route
    through a forecast) with no ice or values given is drawn on the forecast's main field at
    departure, its ice chart's ice and off-chart pixels (seaway.output.voyagemap)."""
    from matplotlib.colors import BoundaryNorm, ListedColormap
    from matplotlib.patches import Patch

    chart = route.chart
    if route.latlon is not None:
        raise SeawayError(
            "a corridor route's chart is in (row, layer) space; plot it with seaway.corridor.plot_corridor"
        )
    m = MapFrame(chart, size, route)
    m.background_land()
    patches = []
    layer, kind = (None, None) if values is not None else ice_layer(route, ice, code)
    land = np.zeros(chart.shape, bool) if chart.land is None else chart.land.astype(bool)
    voyage = voyage_layers(route) if values is None and layer is None else None
    if voyage is not None:  # a weather voyage: the weather it meets, its ice, off chart
        land = voyage.land
        patches, what = _voyage(m, voyage)
    elif layer is not None:
        index, table = classes(layer, kind, fast=fast_ice(route) if ice is None else None)
        present = np.unique(index[(index >= 0) & ~land])
        colours = ListedColormap([np.array(rgb) / 255 for _, rgb in table])
        norm = BoundaryNorm(np.arange(len(table) + 1) - 0.5, len(table))
        m.raster(np.ma.masked_where((index < 0) | land, index), colours, norm)
        patches = [
            Patch(facecolor=np.array(table[k][1]) / 255, edgecolor="#444444", label=table[k][0])
            for k in present
        ]
        what = f"WMO colour code by {'stage of development' if kind == 'stage' else 'total concentration'}"
    else:
        v = np.asarray(chart.values if values is None else values, float)
        im = m.raster(np.ma.masked_where(land | ~np.isfinite(v), v), cmap)
        m.fig.colorbar(im, ax=m.ax, label=label or "cost per unit length", shrink=0.7)
        what = label or "cost per unit length"
    shoal = shoals(route, shoal_m)
    if shoal is not None and (shoal & ~land).any():
        m.raster(
            np.ma.masked_where(~shoal | land, np.ones(shoal.shape)),
            ListedColormap([SHOAL_COLOUR]),
            zorder=2.5,
        )
        patches.append(
            Patch(
                facecolor=SHOAL_COLOUR,
                edgecolor="#444444",
                label=f"shoal: shallower than {float(shoal_m):g} m (draft + UKC)",
            )
        )
    if m.chart_land(land) or chart.geographic:
        patches.append(Patch(facecolor=LAND_COLOUR, edgecolor=COAST_COLOUR, label="land"))
    m.graticule()
    m.route(route)
    if "depth" in route.environment:  # the shallowest point the route crosses
        z, at = least_depth(route, route.environment["depth"])
        if at is not None:
            x, y = point_xy(chart, at)
            m.ax.plot(
                x,
                y,
                "v",
                color=SHOAL_COLOUR,
                mec="black",
                ms=10,
                zorder=9,
                label=f"least depth {z:.1f} m",
                **m.kw,
            )
    m.legend(patches)
    units = "km" if route.geographic else "units"
    nm = f" ({route.length / KM_PER_NM:.0f} nm)" if route.geographic else ""
    m.title(title or f"{route.name}: {route.length:.1f} {units}{nm}, cost {route.cost:.5g}; {what}")
    return m.png(dpi)


def _voyage(m, v):
    """Draw a weather voyage's layers (seaway.output.voyagemap) on the map: (legend patches,
    what the map shows in words)."""
    from matplotlib.colors import BoundaryNorm, ListedColormap
    from matplotlib.patches import Patch

    patches, what = [], []
    if v.field is not None and np.isfinite(v.field).any():
        im = m.raster(np.ma.masked_invalid(v.field), WEATHER_CMAP)
        m.fig.colorbar(im, ax=m.ax, label=v.label, shrink=0.7)
        what.append(v.label)
    if v.ice is not None and np.isfinite(v.ice).any():
        index, table = classes(v.ice, v.code)
        shown = (index >= 0) & ~v.land & ~v.off_chart
        colours = ListedColormap([np.array(rgb) / 255 for _, rgb in table])
        norm = BoundaryNorm(np.arange(len(table) + 1) - 0.5, len(table))
        m.raster(np.ma.masked_where(~shown, index), colours, norm, zorder=2.2)
        by = "stage of development" if v.code == "stage" else "total concentration"
        date = f" (chart of {v.ice_date})" if v.ice_date else ""
        patches = [
            Patch(facecolor=np.array(table[k][1]) / 255, edgecolor="#444444", label=f"ice: {table[k][0]}")
            for k in np.unique(index[shown])
        ]
        what.append(f"ice in the WMO colour code by {by}{date}")
    if v.off_chart.any():
        m.raster(
            np.ma.masked_where(~v.off_chart, np.ones(v.off_chart.shape)),
            ListedColormap([OFF_CHART_COLOUR]),
            zorder=2.4,
        )
        m.hatch(v.off_chart)
        patches.append(
            Patch(facecolor=OFF_CHART_COLOUR, edgecolor="#888888", hatch="///", label=OFF_CHART_LABEL)
        )
    return patches, "; ".join(what) or "no weather field"


def plot_cost_field(
    field, path, *, route=None, lat=None, lon=None, title=None, label=None, size=None, dpi=100
):
    """Write a PNG map of an accumulated-cost field (seaway.cost_field's result: a DataArray, or
    an array with lat/lon), with contours, a colour bar and optionally a route over it. label:
    the colour bar's (default the field's long_name and units, e.g. an arrival field's "hours
    to reach after departure (waiting allowed) (h)")."""
    chart = as_chart(field, lat=lat, lon=lon)  # unreachable pixels (inf) are drawn as land
    m = MapFrame(chart, size, route)
    m.background_land()
    v = np.asarray(chart.values, float)
    im = m.raster(np.ma.masked_where(~np.isfinite(v), v), "viridis")
    m.fig.colorbar(im, ax=m.ax, label=label or _field_label(field), shrink=0.7)
    finite = v[np.isfinite(v)]
    if finite.size and finite.max() > finite.min() and min(v.shape) > 1:
        m.contour(np.where(np.isfinite(v), v, np.nan), levels=10, colors="white", linewidths=0.6, zorder=4)
    m.graticule()
    if route is not None:
        m.route(route, waypoints=False)
        m.legend()
    m.title(title or "accumulated cost")
    write_all([(path, m.png(dpi))])


def _field_label(field) -> str:
    """A field's colour-bar label from its attributes: long_name (units)."""
    attrs = getattr(field, "attrs", {}) or {}
    name = attrs.get("long_name", "least accumulated cost from the start")
    return f"{name} ({attrs['units']})" if attrs.get("units") else name
