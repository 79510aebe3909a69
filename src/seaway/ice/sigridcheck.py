"""What seaway.ice.sigrid checks in a vector ice chart before it rasterises it: errors naming the
file, the features and the fix for what would otherwise read as an empty, partial or wrong chart,
or end in a traceback from GEOS, GDAL or rasterio.

* a shapefile whose .shp, .shx and .dbf disagree (cut short, or from different charts):
  seaway.ice.vectorfile.check_shapefile_records; the features read must then be the records;
* no features, none of the SIGRID-3 fields CT/SA/POLY_TYPE, features that are not polygons;
* a feature whose geometry GEOS cannot read (a damaged file: a ring that does not close, a
  record of the wrong length), or whose coordinates are not finite, or not degrees in a file
  read as lon/lat (a flipped bit in a coordinate);
* no CRS with coordinates that are not degrees."""

from __future__ import annotations

import warnings

import numpy as np

from ..errors import ChartError
from .vectorfile import check_shapefile_records, check_vector_file, one_line

FIX = "fetch the chart again (the download or copy did not finish, or the file is damaged)"


def _which(index, n: int) -> str:
    """'feature 7' or '3 of its 23 features (5, 9, 11)' (1-based, as GIS software counts)."""
    shown = ", ".join(str(int(i) + 1) for i in index[:8]) + (", ..." if len(index) > 8 else "")
    return (
        f"feature {int(index[0]) + 1}" if len(index) == 1 else f"{len(index)} of its {n} features ({shown})"
    )


def expected_records(path, layer=None) -> int | None:
    """The number of features the file says it holds: a shapefile's parts must agree on it
    (ValueError if they do not); other formats (a GeoPackage) as their driver counts them, or
    None when it does not know without reading them all."""
    if str(path).lower().endswith(".shp"):
        check_vector_file(str(path))  # its .dbf and .shx are there, its .prj readable
        return check_shapefile_records(str(path))
    import pyogrio

    try:
        with warnings.catch_warnings():  # GDAL's notes on a damaged file: the read names the damage
            warnings.simplefilter("ignore")
            count = int(pyogrio.read_info(path, layer=layer)["features"])
    except Exception as exc:  # pyogrio's DataSourceError, DataLayerError, ...
        raise ChartError(f"{path}: cannot read it as a SIGRID-3 vector file ({one_line(str(exc))})") from None
    return count if count >= 0 else None


def geometries(path, wkb, expected: int | None):
    """(the features' shapely geometries, None where a feature has none; how many have none),
    checked: as many features as the file's index lists, each readable."""
    import shapely

    if expected is not None and len(wkb) != expected:
        raise ChartError(f"{path}: GDAL read {len(wkb)} features but the file lists {expected}; {FIX}")
    given = np.array([w is not None for w in wkb], bool)
    geoms = shapely.from_wkb(wkb, on_invalid="ignore")
    bad = np.flatnonzero(given & shapely.is_missing(geoms))
    if bad.size:
        try:
            shapely.from_wkb(wkb[bad[0]])
            why = "unreadable"
        except Exception as exc:  # shapely.errors.GEOSException
            why = one_line(str(exc).split(": ", 1)[-1])
        raise ChartError(f"{path}: the geometry of {_which(bad, len(wkb))} cannot be read ({why}); {FIX}")
    return geoms, int((~given).sum())  # features without geometry (a shapefile's null records)


def check_coordinates(path, geoms, crs) -> None:
    """Refuse features whose coordinates are not finite, or not degrees where the file is read
    as lon/lat (its CRS is geographic, or it has none)."""
    import shapely

    present = ~shapely.is_missing(geoms)
    if not present.any():
        return
    box = np.full((len(geoms), 4), np.nan)
    box[present] = shapely.bounds(geoms[present])
    with np.errstate(invalid="ignore"):
        bad = present & ~np.isfinite(box).all(axis=1)
        if _geographic(crs):
            bad |= present & (
                (box[:, 0] < -540) | (box[:, 2] > 540) | (box[:, 1] < -90.001) | (box[:, 3] > 90.001)
            )
    if bad.any():
        k = int(np.flatnonzero(bad)[0])
        raise ChartError(
            f"{path}: {_which(np.flatnonzero(bad), len(geoms))} have coordinates no chart has (e.g. "
            f"x {box[k, 0]:.6g}..{box[k, 2]:.6g}, y {box[k, 1]:.6g}..{box[k, 3]:.6g} in "
            f"{str(crs or 'degrees')[:60]}); {FIX}"
        )


def _geographic(crs) -> bool:
    if not crs:
        return True
    try:
        import pyproj

        return bool(pyproj.CRS.from_user_input(crs).is_geographic)
    except Exception:  # an unparsable CRS: judged elsewhere
        return False


def check_contents(path, meta, fields, geoms) -> None:
    """Errors naming the file for what would otherwise read as an empty or wrong chart."""
    import shapely

    if len(geoms) == 0:
        raise ChartError(f"{path}: the layer has no features (an empty SIGRID-3 chart)")
    if not {"CT", "SA", "POLY_TYPE"} & set(fields):
        raise ChartError(
            f"{path}: none of the SIGRID-3 fields CT, SA, POLY_TYPE is present "
            f"(fields: {sorted(fields)}); is it a SIGRID-3 ice chart?"
        )
    kinds = shapely.get_type_id(geoms)
    other = ~np.isin(kinds, [-1, 3, 6, 7])  # missing, Polygon, MultiPolygon, GeometryCollection
    if other.any():
        types = sorted({g.geom_type for g in geoms[other]})
        raise ChartError(
            f"{path}: {int(other.sum())} of {len(geoms)} features are not polygons "
            f"({', '.join(types)}); SIGRID-3 charts are polygon layers"
        )
    if not meta["crs"]:
        box = shapely.total_bounds(geoms)
        if np.all(np.isfinite(box)) and (np.abs(box[[0, 2]]).max() > 360 or np.abs(box[[1, 3]]).max() > 90):
            raise ChartError(
                f"{path}: the file states no CRS and its coordinates (x {box[0]:.6g}.."
                f"{box[2]:.6g}, y {box[1]:.6g}..{box[3]:.6g}) are not degrees; supply "
                "the .prj file (or set the CRS) so it can be reprojected"
            )
    check_coordinates(path, geoms, meta["crs"])
