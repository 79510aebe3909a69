"""A route's files (``seaway route --out/--plot``): checked before the chart is read or the
route searched (format known from the extension, directory there and writable, the optional
packages the format needs installed), then written all or nothing (seaway.base.files.write_all:
every file to a temporary file beside it, renamed only when all are written)."""

from __future__ import annotations

import importlib.util
import os

from ..base.files import check_output, write_all
from ..errors import SeawayError
from . import export
from .plot import route_png

PLOT_FORMATS = {".png": "png"}
#: The packages a format needs (the [plot] extra), imported only when the files are made.
NEEDS = {"html": ("folium", "js_lib_leaflet"), "png": ("matplotlib",)}


def check_outputs(outs, plot) -> list:
    """[(path, format)] of the --out files and the --plot PNG; ValueError naming the fix for an
    unknown extension, a missing or read-only directory, a path given twice, or a format whose
    packages are not installed."""
    planned = [(p, check_output(p, export.FORMATS, "--out")) for p in outs or []]
    if plot:
        planned.append((plot, check_output(plot, PLOT_FORMATS, "--plot")))
    seen = {}
    for path, _ in planned:
        key = os.path.realpath(path)
        if key in seen:
            raise SeawayError(
                f"{path} is given twice ({seen[key]} and {path}); each output needs its own file"
            )
        seen[key] = path
    for path, fmt in planned:
        missing = [m for m in NEEDS.get(fmt, ()) if importlib.util.find_spec(m) is None]
        if missing:
            raise SeawayError(
                f'{path}: writing {fmt.upper()} needs {", ".join(missing)}: pip install "seaway[plot]"'
            )
    return planned


def write_outputs(planned, route, *, planar=None, title=None, map_options=None, say=print) -> None:
    """Make every planned file of `route` in memory, then write them all or none. `planar`: the
    route on its projected chart, for the PNG (the other outputs take `route`, in lat/lon)."""
    files = []
    for path, fmt in planned:
        if fmt == "png":
            files.append(
                (path, route_png(planar if planar is not None else route, title=title, **(map_options or {})))
            )
        else:
            options = (map_options or {}) if fmt == "html" else {}
            files.append((path, export.render(route, fmt, **options)))
    write_all(files)
    for path, fmt in planned:
        say(f"wrote {path} ({fmt if fmt != 'png' else 'PNG'})")
