"""PNG maps of a route over its chart, and of an accumulated-cost field (matplotlib, an optional
extra: pip install "seaway[plot]"). Drawn in the chart's own lat/lon (or y/x) coordinates with
the Agg backend; cartopy is not needed. The route is drawn in ROUTE_COLOUR."""

from __future__ import annotations

import numpy as np


ROUTE_COLOUR = "#ff00ff"  # magenta: absent from the cost colour map and the land grey
LAND_COLOUR = "#8c8c8c"


def _pyplot():
    try:
        import matplotlib
    except ImportError:
        raise ImportError('plotting needs matplotlib: pip install "seaway[plot]"') from None
    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    return plt


def _extent(chart):
    """imshow extent (left, right, bottom, top) and whether x is longitude."""
    if chart.geographic:
        y, x = chart.lat, np.asarray(chart.lon, float)
        x = np.concatenate([[x[0]], x[0] + np.cumsum((np.diff(x) + 180) % 360 - 180)])
    else:
        y, x = chart.y, chart.x
    hy = (y[-1] - y[0]) / (len(y) - 1) / 2 if len(y) > 1 else 0.5
    hx = (x[-1] - x[0]) / (len(x) - 1) / 2 if len(x) > 1 else 0.5
    return (x[0] - hx, x[-1] + hx, y[-1] + hy, y[0] - hy), x


def _save(fig, path, dpi):
    import os
    import tempfile
    target = os.path.abspath(os.fspath(path))
    fd, tmp = tempfile.mkstemp(dir=os.path.dirname(target), prefix=".seaway-", suffix=".png")
    os.close(fd)
    try:
        fig.savefig(tmp, dpi=dpi, format="png")
        os.replace(tmp, target)
    except BaseException:
        os.unlink(tmp)
        raise


def _raster(ax, chart, values, label, cmap):
    plt = _pyplot()
    extent, _ = _extent(chart)
    v = np.where(np.isfinite(values), values, np.nan).astype(float)
    land = np.zeros(v.shape, bool) if chart.land is None else chart.land.astype(bool)
    land |= ~np.isfinite(values)
    im = ax.imshow(np.ma.masked_where(land, v), extent=extent, origin="upper", cmap=cmap,
                   interpolation="nearest", aspect="auto")
    ax.imshow(np.ma.masked_where(~land, np.ones(v.shape)), extent=extent, origin="upper",
              cmap=plt.matplotlib.colors.ListedColormap([LAND_COLOUR]), interpolation="nearest",
              aspect="auto")
    plt.colorbar(im, ax=ax, label=label, shrink=0.85)
    if chart.geographic:
        ax.set_xlabel("longitude, degrees east")
        ax.set_ylabel("latitude, degrees north")
        ax.set_aspect(1 / np.cos(np.radians(np.mean(chart.lat))))
    else:
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.set_aspect("equal")


def plot_route(route, path, *, values=None, label=None, title=None, size=(8, 6), dpi=100,
               cmap="Blues"):
    """Write a PNG of `values` (default: the route's cost raster) with land in grey, the route
    in magenta and its start (circle) and end (square). size in inches; pixels = size x dpi."""
    plt = _pyplot()
    chart = route.chart
    if route.latlon is not None:
        raise ValueError("a corridor route's chart is in (row, layer) space; plot it with "
                         "seaway.corridor.plot_corridor")
    fig, ax = plt.subplots(figsize=size)
    _raster(ax, chart, chart.values if values is None else np.asarray(values),
            label or "cost per unit length", cmap)
    c = route.coords
    if chart.geographic:
        _, lon = _extent(chart)
        x = lon[0] + ((c[:, 1] - lon[0]) % 360.0)  # the plot's continuous longitudes
        y = c[:, 0]
    else:
        y, x = c[:, 0], c[:, 1]
    ax.plot(x, y, color=ROUTE_COLOUR, lw=2.0, solid_capstyle="round", label="route")
    ax.plot(x[0], y[0], "o", color=ROUTE_COLOUR, mec="black", ms=9, label="start")
    ax.plot(x[-1], y[-1], "s", color=ROUTE_COLOUR, mec="black", ms=9, label="end")
    ax.legend(loc="best", fontsize=8)
    units = "km" if route.geographic else "units"
    ax.set_title(title or f"{route.name}: {route.length:.1f} {units}, cost {route.cost:.5g}",
                 fontsize=10)
    fig.tight_layout()
    _save(fig, path, dpi)
    plt.close(fig)


def plot_cost_field(field, path, *, route=None, lat=None, lon=None, title=None, size=(8, 6),
                    dpi=100):
    """Write a PNG of an accumulated-cost field (seaway.cost_field's result: a DataArray, or an
    array with lat/lon), with contours and optionally a route over it."""
    from ._chart import as_chart
    plt = _pyplot()
    chart = as_chart(field, lat=lat, lon=lon)  # unreachable pixels (inf) are drawn as land
    fig, ax = plt.subplots(figsize=size)
    _raster(ax, chart, chart.values, "least accumulated cost from the start", "viridis")
    finite = chart.values[np.isfinite(chart.values)]
    if finite.size and finite.max() > finite.min():
        extent, _ = _extent(chart)
        ax.contour(np.where(np.isfinite(chart.values), chart.values, np.nan), levels=10,
                   colors="white", linewidths=0.6, extent=(extent[0], extent[1], extent[3], extent[2]),
                   origin="upper")
    if route is not None:
        c = route.coords
        x = c[:, 1]
        if chart.geographic:
            _, lon = _extent(chart)
            x = lon[0] + ((x - lon[0]) % 360.0)
        ax.plot(x, c[:, 0], color=ROUTE_COLOUR, lw=2.0)
    ax.set_title(title or "accumulated cost", fontsize=10)
    fig.tight_layout()
    _save(fig, path, dpi)
    plt.close(fig)
