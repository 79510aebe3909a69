"""The frame of a PNG map (seaway.plot draws on it): a matplotlib figure with one map, cartopy's
polar stereographic projection (north or south by the chart's mean latitude) for lat/lon charts
and plain axes for planar ones, and what every map has: the land around the chart and its own
land mask with their coastlines, rasters and contours drawn in the map's projection, the
graticule, the route with its waypoints and ends, the title, the legend and the PNG bytes."""

from __future__ import annotations

import io

import numpy as np

from .style import COAST_COLOUR, LAND_COLOUR, ROUTE_COLOUR, axes_coords, edges, fit_title, route_xy

MAX_DRAWN = 700  # pixels along a side actually drawn (larger charts are subsampled)
DEFAULT_WIDTH = 11.0  # inches; the height follows the map's aspect unless size is given


def pyplot():
    try:
        import matplotlib
    except ImportError:
        raise ImportError('plotting needs matplotlib: pip install "seaway[plot]"') from None
    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    return plt


def cartopy_crs():
    try:
        import cartopy.crs as ccrs
    except ImportError:
        raise ImportError('polar stereographic maps need cartopy: pip install "seaway[plot]"') from None
    return ccrs


def stride(shape) -> int:
    return max(1, int(np.ceil(max(shape) / MAX_DRAWN)))


class MapFrame:
    """A figure with one map: cartopy polar stereographic for lat/lon charts, plain axes else."""

    def __init__(self, chart, size, route=None):
        plt = pyplot()
        self.plt, self.chart = plt, chart
        self.y, self.x = axes_coords(chart)
        self.fig = plt.figure(figsize=size or (DEFAULT_WIDTH, 0.75 * DEFAULT_WIDTH), layout="constrained")
        if chart.geographic:
            ccrs = cartopy_crs()
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
        k = stride(values.shape)
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
        k = stride(values.shape)
        gx, gy = self._grid(self.y[::k], self.x[::k])
        return self.ax.contour(gx, gy, values[::k, ::k], **kw, **self.map_kw)

    def hatch(self, mask, zorder=2.5):
        """Grey hatching over the pixels of `mask` (off the chart)."""
        if min(mask.shape) < 2:
            return
        with self.plt.rc_context({"hatch.color": "#8c8c8c", "hatch.linewidth": 0.6}):
            self.contour_filled(
                mask.astype(float), levels=[0.5, 1.5], colors="none", hatches=["///"], zorder=zorder
            )

    def contour_filled(self, values, **kw):
        k = stride(values.shape)
        gx, gy = self._grid(self.y[::k], self.x[::k])
        return self.ax.contourf(gx, gy, values[::k, ::k], **kw, **self.map_kw)

    def chart_land(self, land=None):
        """The chart's own land mask (what the router treated as land; or `land`, e.g. without
        the off-chart pixels), with its coastline."""
        land = self.chart.land if land is None else land
        if land is None or not land.any():
            return False
        cmap = self.plt.matplotlib.colors.ListedColormap([LAND_COLOUR])
        self.raster(np.ma.masked_where(land == 0, np.ones(land.shape)), cmap, zorder=3)
        if min(land.shape) > 1:
            self.contour(land.astype(float), levels=[0.5], colors=[COAST_COLOUR], linewidths=0.6, zorder=4)
        return True

    def graticule(self):
        """Parallels and meridians: the meridians labelled where they meet the bottom of the
        frame (straight lines from the pole: the label is on its meridian), the parallels along
        the map's central meridian, each label on its own parallel (where a parallel cuts the
        side of a polar map is far from where it crosses the chart: 70.3 N read as 66 N)."""
        if self.chart.geographic:
            levels = self._parallels()
            gl = self.ax.gridlines(
                draw_labels=True,
                linewidth=0.4,
                color="#555555",
                alpha=0.6,
                linestyle="--",
                x_inline=False,
                y_inline=False,
                zorder=5,
                ylocs=levels,
            )
            gl.top_labels = gl.right_labels = gl.left_labels = False
            gl.rotate_labels = False  # upright labels, as on a printed chart
            gl.xlabel_style = gl.ylabel_style = {"size": 7}
            lon0 = float(self.ax.projection.proj4_params.get("lon_0", 0.0))
            for lat in levels:
                self.ax.text(
                    lon0,
                    lat,
                    f"{abs(lat):g}°{'N' if lat >= 0 else 'S'}",
                    size=7,
                    ha="center",
                    va="center",
                    zorder=5.5,
                    gid="parallel label",
                    bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none", "alpha": 0.7},
                    clip_on=True,
                    **self.kw,
                )
        else:
            self.ax.grid(True, linewidth=0.4, color="#555555", alpha=0.5, linestyle="--")

    def _parallels(self) -> list:
        """The parallels to draw and label: round latitudes (every 1, 2, 2.5, 5 or 10 degrees)
        that cross the map's central meridian inside the frame."""
        from matplotlib.ticker import MaxNLocator

        x0, x1, y0, y1 = self.ax.get_extent()
        ends = self.data_crs.transform_points(self.ax.projection, np.array([0.0, 0.0]), np.array([y0, y1]))
        lo, hi = sorted(float(v) for v in ends[:, 1])
        levels = MaxNLocator(nbins=8, steps=[1, 2, 2.5, 5, 10]).tick_values(lo, hi)
        return [float(v) for v in levels if lo < v < hi and abs(v) < 90]

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
