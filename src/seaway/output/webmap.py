"""Interactive HTML maps of a route (folium / Leaflet, an optional extra: pip install
"seaway[plot]") that open offline: no tile server, and Leaflet's JavaScript and CSS inlined from
the copy the django-js-lib-leaflet package ships instead of linked from a CDN.

Layers: the chart as an image (ice in the WMO colour code, seaway.ice.colours, fast ice grey,
else the cost raster; land tan), the land around it (global-land-mask, shipped with that package), and the
route with a popup at every waypoint: position, the course, distance and time of the leg that
starts there, its cost, and the ice along it. Leaflet's map is Web Mercator, so the image stops
at 85.05 degrees of latitude."""

from __future__ import annotations

import html
import re

import numpy as np

from ..base import sphere as geo
from ..base.files import write_atomically
from ..errors import SeawayError
from ..ice.colours import classes, guess_code
from ..result.environment import least_depth
from ..result.route import ABOVE
from ..result.waypoints import waypoint_list
from .leaflet import inline_leaflet, legend_control, popup_element
from .popup import waypoint_popup
from .style import LAND_COLOUR, ROUTE_COLOUR, SHOAL_COLOUR, edges, fast_ice, ice_layer, route_xy, shoals
from .voyagemap import voyage_layers, voyage_rgba

MERCATOR_LIMIT = 85.051128779806589  # Web Mercator's latitude limit
MAX_IMAGE = 2000  # pixels along a side of the embedded chart image (larger charts subsampled)


def _folium():
    try:
        import folium
    except ImportError:
        raise ImportError('interactive maps need folium: pip install "seaway[plot]"') from None
    return folium


def _mercator_rows(rgba, lat_edges):
    """Resample image rows (north first, regular in latitude between `lat_edges`) to rows regular
    in Web Mercator y, nearest row (class colours are not blended)."""

    def merc(lat):
        return np.degrees(np.arcsinh(np.tan(np.radians(lat))))

    north = min(float(lat_edges[0]), MERCATOR_LIMIT)
    south = max(float(lat_edges[-1]), -MERCATOR_LIMIT)
    rows = rgba.shape[0]
    y = merc(north) + (np.arange(rows) + 0.5) / rows * (merc(south) - merc(north))
    lat = np.degrees(np.arctan(np.sinh(np.radians(y))))
    index = np.clip(np.searchsorted(-np.asarray(lat_edges), -lat) - 1, 0, rows - 1)
    return rgba[index], (south, north)


def _chart_image(route, ice, code, shoal_m=None):
    """(RGBA uint8 image north-up, lat edges north first, lon edges, layer name, legend rows)."""
    chart = route.chart
    k = max(1, int(np.ceil(max(chart.shape) / MAX_IMAGE)))
    land = np.zeros(chart.shape, bool) if chart.land is None else chart.land.astype(bool)
    layer, kind = ice_layer(route, ice, code)
    rgba = np.zeros(chart.shape + (4,), np.uint8)
    legend = []
    voyage = voyage_layers(route) if layer is None else None
    if voyage is not None:  # a weather voyage: the weather it meets, its ice, off chart
        land = voyage.land
        rgba, name, legend = voyage_rgba(voyage)
    elif layer is not None:
        index, table = classes(layer, kind, fast=fast_ice(route))
        colours = np.array([rgb for _, rgb in table], np.uint8).reshape(-1, 3)
        ok = index >= 0
        rgba[ok, :3], rgba[ok, 3] = colours[index[ok]], 255
        legend = [table[i] for i in np.unique(index[ok & ~land])]
        name = (
            f"ice: WMO colour code by {'stage of development' if kind == 'stage' else 'total concentration'}"
        )
    else:
        from matplotlib import colormaps

        v = np.asarray(chart.values, float)
        ok = np.isfinite(v) & (v >= 0)
        lo, hi = (float(v[ok].min()), float(v[ok].max())) if ok.any() else (0.0, 1.0)
        rgba[ok] = (colormaps["viridis"]((v[ok] - lo) / (hi - lo or 1.0)) * 255).astype(np.uint8)
        name = f"cost per unit length ({lo:.3g} dark to {hi:.3g} light)"
    shoal = shoals(route, shoal_m)
    if shoal is not None and (shoal & ~land).any():  # water shallower than draft + UKC
        rgba[shoal] = list(_rgb(SHOAL_COLOUR)) + [255]
        legend.append((f"shoal: shallower than {float(shoal_m):g} m (draft + UKC)", _rgb(SHOAL_COLOUR)))
    rgba[land] = list(_rgb(LAND_COLOUR)) + [255]
    lat = np.asarray(chart.lat, float)[::k]
    lon = geo.unwrap_lon(chart.lon)[::k]
    rgba = rgba[::k, ::k]
    if lat[0] < lat[-1]:  # the image goes north-up ...
        lat, rgba = lat[::-1], rgba[::-1]
    if lon[0] > lon[-1]:  # ... and west to east
        lon, rgba = lon[::-1], rgba[:, ::-1]
    return rgba, edges(lat), edges(lon), name, legend


def _land_around(bounds):
    """RGBA image of the land (global-land-mask) over (south, north, west, east), north-up."""
    from global_land_mask import globe

    south, north, west, east = bounds
    lat = np.linspace(north, south, 400)
    lon = np.linspace(west, east, 800)
    land = globe.is_land(lat[:, None], (lon[None, :] + 180.0) % 360.0 - 180.0)
    rgba = np.zeros(land.shape + (4,), np.uint8)
    rgba[land] = list(_rgb(LAND_COLOUR)) + [255]
    return rgba, edges(lat), edges(lon)


def _rgb(colour: str) -> tuple:
    return tuple(int(colour[i : i + 2], 16) for i in (1, 3, 5))


def explore(route, *, ice=None, code=None, speed_kn=None, zoom_start=None, shoal_m=None):
    """A folium.Map of the route over its chart (geopandas' explore() style): the chart image
    (ice in the WMO colour code when the route carries ice or `ice` is given, else the cost;
    fast ice as fast ice), the land around it, and the route with a popup per waypoint, its
    start a circle and its end a square; a legend (a Leaflet control in the bottom-right
    corner, stacked with the others). Works offline (see the module).

    ice, code, shoal_m: as in seaway.plot.route_png (shoals and the least depth with a depth
    environment). speed_kn: for the legs' times (default the route's)."""
    folium = _folium()
    if not route.geographic or route.latlon is not None:
        raise SeawayError(
            "an interactive map needs a route on a lat/lon chart (not a planar or "
            "corridor chart); use seaway.plot.plot_route for a PNG"
        )
    if ice is not None:
        name = "stage_of_development" if (code or _guess(ice)) == "stage" else "sea_ice_concentration"
        route = route.with_environment({name: ice})
    rgba, lat_e, lon_e, layer_name, legend = _chart_image(route, None, code, shoal_m)
    x, y = route_xy(route, route.chart)
    centre = [float(np.mean(y)), float(np.mean(x))]
    m = folium.Map(location=centre, zoom_start=zoom_start or 4, tiles=None, control_scale=True)
    m.default_js, m.default_css = [], []  # no CDN: _inline_leaflet puts Leaflet in the page
    m.add_child(inline_leaflet(folium))
    south, north = float(lat_e.min()), float(lat_e.max())
    pad = 0.15 * max(north - south, 1.0)
    around = (
        max(south - pad, -MERCATOR_LIMIT),
        min(north + pad, MERCATOR_LIMIT),
        float(lon_e.min()) - 2 * pad,
        float(lon_e.max()) + 2 * pad,
    )
    land, l_lat, l_lon = _land_around(around)
    for image, lats, lons, label, opacity in (
        (land, l_lat, l_lon, "land (global-land-mask)", 1.0),
        (rgba, lat_e, lon_e, layer_name, 0.85),
    ):
        image, (s, n) = _mercator_rows(image, lats)
        folium.raster_layers.ImageOverlay(
            image,
            bounds=[[s, float(lons[0])], [n, float(lons[-1])]],
            opacity=opacity,
            name=label,
            pixelated=True,
        ).add_to(m)
    speed = route.speed_kn if speed_kn is None else speed_kn
    legs = route.legs(speed)
    line = folium.FeatureGroup(name="route").add_to(m)
    wl = waypoint_list(route)  # the waypoints every export gives (seaway.result.waypoints)
    positions = np.column_stack([y, x])[wl.index]
    folium.PolyLine(
        positions.tolist(),
        color=ROUTE_COLOUR,
        weight=4,
        tooltip=f"{html.escape(route.name)}: {route.length:.1f} km "
        f"({route.length / geo.KM_PER_NM:.1f} nm), cost {route.cost:.6g}",
    ).add_to(line)
    last = len(wl) - 1
    for n in range(len(wl)):
        leg = legs[n] if n < len(legs) else None
        if n == last and n > 0:  # the end: a square, the start a circle
            marker = folium.Marker(
                positions[n].tolist(),
                tooltip="end",
                icon=folium.DivIcon(
                    html=f'<div style="width:12px;height:12px;background:{ROUTE_COLOUR};'
                    'border:2px solid black"></div>',
                    icon_size=(16, 16),
                    icon_anchor=(8, 8),
                ),
            )
        else:
            marker = folium.CircleMarker(
                positions[n].tolist(),
                radius=8 if n == 0 else 4,
                weight=1,
                color="black",
                fill=True,
                fill_opacity=1.0,
                tooltip="start" if n == 0 else None,
                fill_color=ROUTE_COLOUR if n == 0 else "white",
            )
        marker.add_to(line)
        marker.add_child(popup_element(waypoint_popup(route, n + 1, wl.coords[n], leg, speed)))
    rows = legend + [("land", _rgb(LAND_COLOUR))] + _marks(folium, route, line)
    folium.LayerControl(collapsed=False).add_to(m)
    m.add_child(legend_control(layer_name, rows))
    m.fit_bounds([[float(np.min(y)), float(np.min(x))], [float(np.max(y)), float(np.max(x))]])
    return m


def _marks(folium, route, line) -> list:
    """The least-depth point (with a depth environment) on the map, and the legend rows of the
    route's marks."""
    dot = (
        '<span style="display:inline-block;width:10px;height:10px;border-radius:50%;'
        'border:1px solid black;margin-right:4px;background:{}"></span>'
    )
    rows = [
        (dot.format(ROUTE_COLOUR) + "start", None),
        (dot.format(ROUTE_COLOUR).replace("border-radius:50%;", "") + "end", None),
    ]
    if "depth" in route.environment:
        z, at = least_depth(route, route.environment["depth"])
        if at is not None:
            text = f"least depth {z:.1f} m"
            folium.CircleMarker(
                list(at),
                radius=6,
                weight=2,
                color="black",
                fill=True,
                fill_opacity=1.0,
                fill_color=SHOAL_COLOUR,
                tooltip=text,
            ).add_to(line)
            rows.append((dot.format(SHOAL_COLOUR) + html.escape(text), None))
    return rows


def _guess(ice):
    return guess_code(np.asarray(getattr(ice, "values", ice), float))


def html_text(route, **options) -> str:
    """The page of explore(route, **options) as one self-contained HTML string."""
    page = explore(route, **options).get_root().render()
    remote = re.findall(
        r"<(?:script|link)\b[^>]*\b(?:src|href)\s*=\s*[\"']?(?:https?:)?//[^>]*>", page, flags=re.I
    )
    if remote:  # a folium element brought its own CDN link: the page would not work offline
        raise RuntimeError(f"the HTML map would load {remote[0]!r} from the network")
    return page


def to_html(route, path, **options) -> None:
    """Write explore(route, **options) to `path` as one self-contained HTML file (atomically)."""
    write_atomically(path, html_text(route, **options))


ABOVE.update(explore=explore, to_html=to_html)  # Route.explore(), Route.to_html()
