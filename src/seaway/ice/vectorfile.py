"""Check a vector chart file before GDAL reads it, so that what is wrong with it is named.

GDAL opens a shapefile without its .prj (and then knows no CRS), with an unreadable .prj (and
then ignores it), and says "not recognized as being in a supported file format" for an empty
file or a directory. A navigator needs to know which: `check_vector_file` refuses what cannot
be read, naming the missing or broken part and the fix, and returns the assumptions reading it
will make (a shapefile without .prj is read as WGS 84 lon/lat), for the caller to say."""

from __future__ import annotations

import os

#: The parts of a shapefile GDAL needs besides the .shp.
SIDECARS = {".dbf": "its attribute table (the SIGRID-3 fields CT, SA, ...)", ".shx": "its index of shapes"}


def _sidecar(path: str, ext: str) -> str | None:
    stem = os.path.splitext(path)[0]
    for e in (ext, ext.upper()):
        if os.path.exists(stem + e):
            return stem + e
    return None


def check_vector_file(path: str, bounds=None) -> list[str]:
    """Refuse (ValueError) a vector chart file that cannot be read as given; return the
    assumptions reading it makes. bounds: the layer's (west, south, east, north), when known,
    to tell whether coordinates of a shapefile without .prj can be degrees."""
    path = str(path)
    if os.path.isdir(path):
        inside = sorted(f for f in os.listdir(path) if os.path.splitext(f)[1].lower() in (".shp", ".gpkg"))
        hint = f"; it holds {', '.join(inside[:5])}" if inside else ""
        raise ValueError(
            f"{path} is a directory, not a chart file; give the chart file (.shp or .gpkg) inside it{hint}"
        )
    if not os.path.exists(path):
        raise ValueError(f"{path}: no such file")
    if os.path.getsize(path) == 0:
        raise ValueError(
            f"{path} is empty (0 bytes): the download or copy did not finish; fetch the chart again"
        )
    if os.path.splitext(path)[1].lower() != ".shp":
        return []
    for ext, what in SIDECARS.items():
        if _sidecar(path, ext) is None:
            raise ValueError(
                f"{path}: the shapefile's {ext} ({what}) is missing; copy "
                f"{os.path.basename(os.path.splitext(path)[0])}{ext} from the chart's "
                "archive next to it"
            )
    prj = _sidecar(path, ".prj")
    if prj is None:
        if bounds is not None and not _degrees(bounds):
            raise ValueError(
                f"{path} has no .prj and its coordinates ({_fmt(bounds)}) are not "
                "degrees, so its CRS is unknown; copy the .prj from the chart's "
                "archive next to it"
            )
        return [
            f"{os.path.basename(path)} has no .prj: its coordinates are read as WGS 84 "
            "longitude/latitude (EPSG:4326), an assumption; add the .prj to be sure"
        ]
    try:
        import pyproj

        with open(prj, encoding="utf-8", errors="replace") as f:
            text = f.read().strip()
        pyproj.CRS.from_user_input(text)
    except ImportError:
        return []
    except Exception as exc:  # pyproj's CRSError, or an empty .prj
        raise ValueError(
            f"{prj} does not describe a CRS ({str(exc)[:120]}); replace it with the "
            "chart archive's .prj, or delete it to read the chart as WGS 84 "
            "lon/lat"
        ) from None
    return []


def _degrees(bounds) -> bool:
    west, south, east, north = bounds
    return bool(-180 <= west <= east <= 360 and -90 <= south <= north <= 90)


def _fmt(bounds) -> str:
    return "x {:.6g}..{:.6g}, y {:.6g}..{:.6g}".format(bounds[0], bounds[2], bounds[1], bounds[3])


__all__ = ["check_vector_file"]
