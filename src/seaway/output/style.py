"""What the PNG and HTML maps share: the colours, pixel edges and axes, the route on them and
the ice layer to colour by."""

from __future__ import annotations

import textwrap

import numpy as np

from ..base.sphere import unwrap_lon
from ..errors import ChartError
from ..ice.colours import guess_code

ROUTE_COLOUR = "#ff00ff"  # magenta, outlined in black: absent from the WMO colours and the greys
LAND_COLOUR = "#c8b996"  # light tan: grey is fast ice in the WMO colour code
COAST_COLOUR = "#303030"
NO_DATA_COLOUR = "#ffffff"
SHOAL_COLOUR = "#00e5e5"  # cyan: water shallower than draft + UKC (absent from the WMO colours)


def edges(centres) -> np.ndarray:
    """Cell edges from (regular or not) pixel centres."""
    c = np.asarray(centres, float)
    if c.size == 1:
        return np.array([c[0] - 0.5, c[0] + 0.5])
    mid = (c[:-1] + c[1:]) / 2
    return np.concatenate([[2 * c[0] - mid[0]], mid, [2 * c[-1] - mid[-1]]])


def axes_coords(chart):
    """Pixel-centre (y, x): lat and continuous lon on geographic charts, y/x otherwise."""
    if chart.geographic:
        return np.asarray(chart.lat, float), unwrap_lon(chart.lon)
    return np.asarray(chart.y, float), np.asarray(chart.x, float)


def route_xy(route, chart):
    """(x, y) of the route's vertices on the axes of axes_coords()."""
    c = route.coords
    if chart.geographic:
        lon0 = unwrap_lon(chart.lon)[0]
        return lon0 + ((c[:, 1] - lon0) % 360.0), c[:, 0]
    return c[:, 1], c[:, 0]


def point_xy(chart, p):
    """(x, y) of one point (lat, lon or y, x) on the axes of axes_coords()."""
    if chart.geographic:
        lon0 = unwrap_lon(chart.lon)[0]
        return lon0 + ((p[1] - lon0) % 360.0), p[0]
    return p[1], p[0]


def fast_ice(route):
    """Mask of the fast ice (form FA 08) on the route's chart, from its environment; or None."""
    fa = route.environment.get("FA")
    return None if fa is None else np.asarray(fa, float) == 8


def shoals(route, shoal_m):
    """Mask of water shallower than `shoal_m` metres (the route's depth environment), or None."""
    depth = route.environment.get("depth")
    if shoal_m is None or depth is None:
        return None
    z = np.asarray(depth, float)
    with np.errstate(invalid="ignore"):
        return (z > 0) & (z < float(shoal_m))


def ice_layer(route, ice, code):
    """(values, code) of the ice to colour by: `ice` if given, else the route's environment
    (stage_of_development / SA, else sea_ice_concentration / CT); (None, None) if none."""
    if ice is None:
        env = route.environment
        for name, kind in (
            ("stage_of_development", "stage"),
            ("SA", "stage"),
            ("sea_ice_concentration", "concentration"),
            ("CT", "concentration"),
        ):
            if name in env and (code is None or code == kind):
                return np.asarray(env[name], float), kind
        return None, None
    if hasattr(ice, "dims") and route.chart.template is not None:
        ice = ice.transpose(*route.chart.template.dims)
    ice = np.asarray(getattr(ice, "values", ice), float)
    if ice.shape != route.chart.shape:
        raise ChartError(
            f"ice has shape {ice.shape} but the chart has {route.chart.shape}; give "
            "the ice raster on the chart's grid"
        )
    return ice, code or guess_code(ice)


def _shorten_path(word: str, room: int) -> str:
    """A file path longer than `room` characters as '.../' and its last parts that fit."""
    parts = word.split("/")
    if len(word) <= room or len(parts) < 3:
        return word
    tail = parts[-1]
    for part in reversed(parts[1:-1]):
        if len(tail) + len(part) + 5 > room:
            break
        tail = part + "/" + tail
    return ".../" + tail


def fit_title(text: str, width: int, lines: int = 3) -> str:
    """`text` on at most `lines` lines of `width` characters: long paths shortened to their
    last parts, then wrapped at spaces; what still does not fit ends in '...' (never cut at the
    figure's edge)."""
    words = [_shorten_path(w, width // 2) for w in text.split(" ")]
    wrapped = textwrap.wrap(
        " ".join(words),
        width,
        break_long_words=True,
        break_on_hyphens=False,
        max_lines=lines,
        placeholder=" ...",
    )
    return "\n".join(wrapped)
