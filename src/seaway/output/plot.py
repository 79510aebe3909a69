"""PNG maps of a route over its chart, and of an accumulated-cost field (matplotlib and cartopy,
an optional extra: pip install "seaway[plot]").

Geographic charts are drawn as ice services draw ice charts: on a polar stereographic map
(north or south by the chart's mean latitude) with a graticule and a coastline, ice in the WMO
colour code (seaway.ice.colours: by total concentration or by stage of development) with a
legend, and the route in ROUTE_COLOUR with its waypoints and ends. The coastline never comes from
the network (cartopy's Natural Earth download): land is the chart's own land mask, and around
it the 1-km global land mask that the global-land-mask package ships. Planar (y/x) charts are
drawn on plain axes. A raster without an ice code (a cost, a cost field) keeps its colour bar."""

from __future__ import annotations

import io

import numpy as np

from ..base.files import write_all
from ..base.units import KM_PER_NM
from ..chart.raster import as_chart
from ..ice.colours import classes
from ..result.environment import least_depth
from .style import (
    COAST_COLOUR,
    LAND_COLOUR,
    ROUTE_COLOUR,
    SHOAL_COLOUR,
    axes_coords,
    edges,
    fast_ice,
    fit_title,
    ice_layer,
    point_xy,
    route_xy,
    shoals,
)

MAX_DRAWN = 700  # pixels along a side actually drawn (larger charts are subsampled)
DEFAULT_WIDTH = 11.0  # inches; the height follows the map's aspect unless size is given


def _pyplot():
    try:
        import matplotlib
    except ImportError:
        raise ImportError('plotting needs matplotlib: pip install "seaway[plot]"') from None
    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    return plt


def _cartopy():
    try:
        import cartopy.crs as ccrs
    except ImportError:
        raise ImportError('polar stereographic maps need cartopy: pip install "seaway[plot]"') from None
    return ccrs


def _stride(shape) -> int:
    return max(1, int(np.ceil(max(shape) / MAX_DRAWN)))


class _Map:
    """A figure with one map: cartopy polar stereographic for lat/lon charts, plain axes else."""

    def __init__(self, chart, size, route=None):
        plt = _pyplot()
        self.plt, self.chart = plt, chart
        self.y, self.x = axes_coords(chart)
        self.fig = plt.figure(figsize=size or (DEFAULT_WIDTH, 0.75 * DEFAULT_WIDTH), layout="constrained")
        if chart.geographic:
            ccrs = _cartopy()
            south, north = float(np.min(self.y)), float(np.max(self.y))
            xs = [float(self.x.min()), float(self.x.max())]
            ys = [south, north]
            if route is not None:
                rx, ry = route_xy(route, chart)
                xs += [float(rx.min()), float(rx.max())]
                ys += [float(ry.min()), float(ry.max())]
            centre = (min(xs) + max(xs)) / 2
            polar = ccrs.NorthPolarStereo if (south + north) / 2 >= 0 else ccrs.SouthPolarStereo
            self.data_crs = ccrs.PlateCarree()
            self.line_crs = ccrs.Geodetic()
            self.ax = self.fig.add_subplot(projection=polar(central_longitude=centre))
            pad_y, pad_x = 0.03 * (max(ys) - min(ys)) + 0.1, 0.03 * (max(xs) - min(xs)) + 0.1
            self.bounds = (
                min(xs) - pad_x,
                max(xs) + pad_x,
                max(min(ys) - pad_y, -90.0),
                min(max(ys) + pad_y, 90.0),
            )
            self.ax.set_extent(self.bounds, crs=self.data_crs)
            if size is None:
                self._fit_height()
            self.kw = {"transform": self.data_crs}
            self.map_kw = {"transform": self.ax.projection}
            self.line_kw = {"transform": self.line_crs}
        else:
            self.ax = self.fig.add_subplot()
            self.ax.set_aspect("equal")
            self.ax.set_xlabel("x")
            self.ax.set_ylabel("y")
            self.kw, self.line_kw, self.map_kw = {}, {}, {}
            if self.y[-1] > self.y[0]:
                self.ax.invert_yaxis()  # row 0 on top, as the raster is printed

    def _fit_height(self):
        """Figure height for the map's own aspect (no band of white above and below it): the
        map takes the width left by the legend (about 3 inches), plus room for title and labels."""
        x0, x1, y0, y1 = self.ax.get_extent()
        height = (DEFAULT_WIDTH - 3.0) * (y1 - y0) / (x1 - x0) + 1.3
        self.fig.set_size_inches(DEFAULT_WIDTH, float(np.clip(height, 4.0, 1.4 * DEFAULT_WIDTH)))

    def _grid(self, y, x):
        """2-D map coordinates of points (y, x): projected once with numpy for lat/lon charts
        (contouring or meshing in the projection avoids cartopy's slow polygon reprojection)."""
        gx, gy = np.meshgrid(x, y)
        if not self.chart.geographic:
            return gx, gy
        p = self.ax.projection.transform_points(self.data_crs, gx, gy)
        return p[..., 0], p[..., 1]

    def background_land(self):
        """Land around and under the chart (global-land-mask's 1-km mask, shipped with the
        package: no network), with its coastline."""
        if not self.chart.geographic:
            return
        from global_land_mask import globe

        w, e, s, n = self.bounds
        lat, lon = np.linspace(s, n, 400), np.linspace(w, e, 600)
        glon, glat = np.meshgrid(lon, lat)
        land = globe.is_land(glat, (glon + 180.0) % 360.0 - 180.0).astype(float)
        if land.any() and not land.all():
            gx, gy = self._grid(lat, lon)
            self.ax.contourf(gx, gy, land, levels=[0.5, 1.5], colors=[LAND_COLOUR], zorder=1, **self.map_kw)
            self.ax.contour(
                gx, gy, land, levels=[0.5], colors=[COAST_COLOUR], linewidths=0.6, zorder=4, **self.map_kw
            )
        elif land.all():
            self.ax.set_facecolor(LAND_COLOUR)

    def raster(self, values, cmap, norm=None, zorder=2):
        k = _stride(values.shape)
        gx, gy = self._grid(edges(self.y[::k]), edges(self.x[::k]))
        return self.ax.pcolormesh(
            gx,
            gy,
            values[::k, ::k],
            cmap=cmap,
            norm=norm,
            shading="flat",
            zorder=zorder,
            rasterized=True,
            **self.map_kw,
        )

    def contour(self, values, **kw):
        k = _stride(values.shape)
        gx, gy = self._grid(self.y[::k], self.x[::k])
        return self.ax.contour(gx, gy, values[::k, ::k], **kw, **self.map_kw)

    def chart_land(self):
        """The chart's own land mask (what the router treated as land), with its coastline."""
        land = self.chart.land
        if land is None or not land.any():
            return False
        cmap = self.plt.matplotlib.colors.ListedColormap([LAND_COLOUR])
        self.raster(np.ma.masked_where(land == 0, np.ones(land.shape)), cmap, zorder=3)
        if min(land.shape) > 1:
            self.contour(land.astype(float), levels=[0.5], colors=[COAST_COLOUR], linewidths=0.6, zorder=4)
        return True

    def graticule(self):
        if self.chart.geographic:
            gl = self.ax.gridlines(
                draw_labels=True,
                linewidth=0.4,
                color="#555555",
                alpha=0.6,
                linestyle="--",
                x_inline=False,
                y_inline=False,
                zorder=5,
            )
            gl.top_labels = gl.right_labels = False
            gl.rotate_labels = False  # upright labels, as on a printed chart
            gl.xlabel_style = gl.ylabel_style = {"size": 7}
        else:
            self.ax.grid(True, linewidth=0.4, color="#555555", alpha=0.5, linestyle="--")

    def route(self, route, waypoints=True):
        from matplotlib import patheffects

        x, y = route_xy(route, self.chart)
        halo = [patheffects.Stroke(linewidth=4.0, foreground="black"), patheffects.Normal()]
        self.ax.plot(
            x,
            y,
            color=ROUTE_COLOUR,
            lw=2.0,
            solid_capstyle="round",
            zorder=6,
            path_effects=halo,
            label="route",
            **self.line_kw,
        )
        if waypoints and len(route.waypoint_index) > 2:
            wi = route.waypoint_index[1:-1]
            self.ax.plot(
                x[wi],
                y[wi],
                "o",
                color="white",
                mec="black",
                ms=3,
                mew=0.6,
                zorder=7,
                label=f"waypoints ({len(wi)} course changes)",
                **self.kw,
            )
        self.ax.plot(
            x[0], y[0], "o", color=ROUTE_COLOUR, mec="black", ms=9, zorder=8, label="start", **self.kw
        )
        self.ax.plot(
            x[-1], y[-1], "s", color=ROUTE_COLOUR, mec="black", ms=9, zorder=8, label="end", **self.kw
        )

    def title(self, text):
        width = max(int(self.fig.get_size_inches()[0] * 10), 30)  # 10-point characters across
        self.fig.suptitle(fit_title(text, width), fontsize=10)

    def legend(self, extra=()):
        handles, labels = self.ax.get_legend_handles_labels()
        handles, labels = list(extra) + handles, [h.get_label() for h in extra] + labels
        self.fig.legend(handles, labels, loc="outside right center", fontsize=8, frameon=False)

    def png(self, dpi) -> bytes:
        """The figure as PNG bytes (the figure is closed)."""
        buffer = io.BytesIO()
        try:
            self.fig.savefig(buffer, dpi=dpi, format="png")
        finally:
            self.plt.close(self.fig)
        return buffer.getvalue()


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
    Fast ice (an FA environment, form 08) is drawn as fast ice."""
    from matplotlib.colors import BoundaryNorm, ListedColormap
    from matplotlib.patches import Patch

    chart = route.chart
    if route.latlon is not None:
        raise ValueError(
            "a corridor route's chart is in (row, layer) space; plot it with seaway.corridor.plot_corridor"
        )
    m = _Map(chart, size, route)
    m.background_land()
    patches = []
    layer, kind = (None, None) if values is not None else ice_layer(route, ice, code)
    land = np.zeros(chart.shape, bool) if chart.land is None else chart.land.astype(bool)
    if layer is not None:
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
    if m.chart_land() or chart.geographic:
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


def plot_cost_field(field, path, *, route=None, lat=None, lon=None, title=None, size=None, dpi=100):
    """Write a PNG map of an accumulated-cost field (seaway.cost_field's result: a DataArray, or
    an array with lat/lon), with contours, a colour bar and optionally a route over it."""
    chart = as_chart(field, lat=lat, lon=lon)  # unreachable pixels (inf) are drawn as land
    m = _Map(chart, size, route)
    m.background_land()
    v = np.asarray(chart.values, float)
    im = m.raster(np.ma.masked_where(~np.isfinite(v), v), "viridis")
    m.fig.colorbar(im, ax=m.ax, label="least accumulated cost from the start", shrink=0.7)
    finite = v[np.isfinite(v)]
    if finite.size and finite.max() > finite.min() and min(v.shape) > 1:
        m.contour(np.where(np.isfinite(v), v, np.nan), levels=10, colors="white", linewidths=0.6, zorder=4)
    m.graticule()
    if route is not None:
        m.route(route, waypoints=False)
        m.legend()
    m.title(title or "accumulated cost")
    write_all([(path, m.png(dpi))])
