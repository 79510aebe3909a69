"""Check a vector chart file before GDAL reads it, so that what is wrong with it is named.

GDAL opens a shapefile without its .prj (and then knows no CRS), with an unreadable .prj (and
then ignores it), and says "not recognized as being in a supported file format" for an empty
file or a directory. A navigator needs to know which: `check_vector_file` refuses what cannot
be read, naming the missing or broken part and the fix, and returns the assumptions reading it
will make (a shapefile without .prj is read as WGS 84 lon/lat), for the caller to say.

GDAL also reads a damaged shapefile without complaint: a .shp cut short gives the features past
the cut no geometry (a chart truncated to 90 % lost 2 of its 23 polygons, silently), and a .dbf
cut short drops their attributes. `check_shapefile_records` reads the three headers (the .shp's
declared length, the .shx index of record offsets, the .dbf's record count) and refuses a file
whose parts disagree, naming the records lost and the fix."""

from __future__ import annotations

import os
import struct

from ..base.validate import one_line
from ..errors import ChartError

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
        raise ChartError(
            f"{path} is a directory, not a chart file; give the chart file (.shp or .gpkg) inside it{hint}"
        )
    if not os.path.exists(path):
        raise ChartError(f"{path}: no such file")
    if os.path.getsize(path) == 0:
        raise ChartError(
            f"{path} is empty (0 bytes): the download or copy did not finish; fetch the chart again"
        )
    if os.path.splitext(path)[1].lower() != ".shp":
        return []
    for ext, what in SIDECARS.items():
        if _sidecar(path, ext) is None:
            raise ChartError(
                f"{path}: the shapefile's {ext} ({what}) is missing; copy "
                f"{os.path.basename(os.path.splitext(path)[0])}{ext} from the chart's "
                "archive next to it"
            )
    prj = _sidecar(path, ".prj")
    if prj is None:
        if bounds is not None and not _degrees(bounds):
            raise ChartError(
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
        raise ChartError(
            f"{prj} does not describe a CRS ({one_line(str(exc), 120)}); replace it with the "
            "chart archive's .prj, or delete it to read the chart as WGS 84 "
            "lon/lat"
        ) from None
    return []


def _header(path: str, what: str) -> tuple[bytes, int]:
    """The first 100 bytes of a .shp or .shx (its header), checked, and the file's size."""
    size = os.path.getsize(path)
    with open(path, "rb") as f:
        head = f.read(100)
    if size < 100:
        raise ChartError(
            f"{path} is cut short: {size} bytes, less than a shapefile {what}'s 100-byte header; "
            "fetch the chart again"
        )
    if struct.unpack(">i", head[:4])[0] != 9994:
        raise ChartError(
            f"{path} is not a shapefile {what}: it starts {head[:4].hex()}, a shapefile "
            "0000270a; fetch the chart again"
        )
    return head, size


def _records(first: int, last: int, total: int) -> str:
    return f"record {first}" if first == last else f"records {first}-{last} of {total}"


def check_shapefile_records(path: str) -> int:
    """The number of records of a shapefile whose .shp, .shx and .dbf agree; else ValueError
    naming the part that is cut short or does not match, the records lost and the fix."""
    fix = "fetch the chart again (the download or copy did not finish, or the file is damaged)"
    head, size = _header(path, "(.shp)")
    declared = 2 * struct.unpack(">i", head[24:28])[0]
    shx = _sidecar(path, ".shx") or ""
    index_head, index_size = _header(shx, "index (.shx)")
    n = (index_size - 100) // 8
    if 2 * struct.unpack(">i", index_head[24:28])[0] != index_size or (index_size - 100) % 8:
        raise ChartError(
            f"{shx}: the index declares {2 * struct.unpack('>i', index_head[24:28])[0]} bytes but "
            f"has {index_size}; {fix}"
        )
    with open(shx, "rb") as f:
        f.seek(100)
        index = f.read(8 * n)
    entries = list(struct.iter_unpack(">ii", index))  # each record's offset and length (words)
    past = [i for i, (o, c) in enumerate(entries) if 2 * (o + c) + 8 > size]
    if size < declared or past:
        lost = (
            f"{len(past)} of its {n} features ({_records(past[0] + 1, past[-1] + 1, n)}) lie"
            if past
            else "no feature lies"
        )
        raise ChartError(
            f"{path} is cut short: it has {size} of the {declared} bytes its header declares, and "
            f"{lost} in the missing part; {fix}"
        )
    with open(path, "rb") as f:  # each record where the index says, as long as it says
        for i, (o, c) in enumerate(entries):
            f.seek(2 * o)
            head = f.read(8)
            if 2 * o < 100 or struct.unpack(">ii", head)[1] != c:
                raise ChartError(
                    f"{shx}: its entry for record {i + 1} of {n} does not point at that record in "
                    f"the .shp (offset {2 * o}); the index is damaged or from another chart; {fix}"
                )
    dbf = _sidecar(path, ".dbf") or ""
    with open(dbf, "rb") as f:
        table = f.read(32)
    if len(table) < 12:
        raise ChartError(f"{dbf} is not a dBASE table ({os.path.getsize(dbf)} bytes); {fix}")
    rows, head_len, row_len = struct.unpack("<IHH", table[4:12])
    whole = (os.path.getsize(dbf) - head_len) // row_len if row_len else rows
    if whole < rows:
        raise ChartError(
            f"{dbf} holds {max(whole, 0)} of the {rows} attribute records its header declares: "
            f"it is cut short or damaged (the attributes of {_records(max(whole, 0) + 1, rows, rows)} "
            f"are lost); {fix}"
        )
    if rows != n:
        raise ChartError(
            f"{path}: its index (.shx) lists {n} features but its attribute table (.dbf) {rows}; "
            f"the parts come from different charts or one is damaged; {fix}"
        )
    return n


def _degrees(bounds) -> bool:
    west, south, east, north = bounds
    return bool(-180 <= west <= east <= 360 and -90 <= south <= north <= 90)


def _fmt(bounds) -> str:
    return "x {:.6g}..{:.6g}, y {:.6g}..{:.6g}".format(bounds[0], bounds[2], bounds[1], bounds[3])


__all__ = ["check_vector_file", "check_shapefile_records", "one_line"]
