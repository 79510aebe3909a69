"""What a season of SIGRID-3 charts covers (seaway.voyage.season.open_season): the union of the
charts' extents in degrees, and which chart leaves an end or most of the grid uncovered."""

from __future__ import annotations

import warnings

import numpy as np

from ..base.validate import one_line
from ..errors import ChartError
from .vectorchart import in_degrees


def charts_bounds(charts):
    """The union of the charts' extents in degrees, or None when one is not in degrees."""
    import pyogrio

    boxes = []
    for _, path in charts:
        try:
            with warnings.catch_warnings():  # GDAL's notes on a damaged file: the read names it
                warnings.simplefilter("ignore")
                info = pyogrio.read_info(path)
        except Exception as exc:  # pyogrio's DataSourceError, ...
            raise ChartError(f"{path}: cannot read it as a SIGRID-3 vector file ({one_line(exc)})") from None
        if not in_degrees(info):
            return None
        boxes.append(info["total_bounds"])
    b = np.array(boxes, float)
    return b[:, 0].min(), b[:, 1].min(), b[:, 2].max(), b[:, 3].max()


def check_cover(ds, charts, ends, target) -> list[str]:
    """Say which chart does not cover an end (ChartError), or most of the grid (a note): off a
    chart's polygons the ice is unknown, so impassable; that is the chart's extent, not the ice."""
    off = np.asarray(ds["off_chart"].values)
    lat, lon = np.asarray(target.y, float), np.asarray(target.x, float)
    notes = []
    for k, (date, path) in enumerate(charts):
        for name, p in zip(("start", "end"), ends or ()):
            r = int(np.argmin(np.abs(lat - p[0])))
            c = int(np.argmin(np.abs((lon - p[1] + 180) % 360 - 180)))
            if off[k, r, c]:
                raise ChartError(
                    f"the chart of {date} ({path}) does not cover the {name} {p[0]:g},{p[1]:g}: no polygon "
                    "of it lies there, so its ice is unknown; give a chart that covers the voyage, or set "
                    "the grid with --grid"
                )
        share = float(off[k].mean())
        if share > 0.05:
            notes.append(
                f"the chart of {date} ({path}) leaves {100 * share:.0f} % of the grid uncovered: "
                "off its polygons the ice is unknown and impassable"
            )
    return notes
