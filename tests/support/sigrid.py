"""Small synthetic SIGRID-3 shapefiles in lon/lat (EPSG:4326), as the real charts are written:
text codes, -9 where an attribute does not apply (used by ice/test_forms.py, cli/test_cli_ends.py,
ice/test_noroute.py)."""

import warnings

import numpy as np

FIELDS = ["POLY_TYPE", "CT", "CA", "SA", "FA", "CB", "SB", "FB", "CC", "SC", "FC"]


def write_chart(path, rows):
    """Write [(shapely polygon, {field: code text}), ...] as a SIGRID-3 shapefile at `path`."""
    import pyogrio.raw
    import shapely

    geoms = np.array(shapely.to_wkb([g for g, _ in rows]), dtype=object)
    fields = [np.array([attrs.get(n, "-9") for _, attrs in rows], dtype=object) for n in FIELDS]
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message=".*winding", category=RuntimeWarning)
        pyogrio.raw.write(
            str(path),
            geoms,
            fields,
            fields=FIELDS,
            geometry_type="Polygon",
            crs="EPSG:4326",
            driver="ESRI Shapefile",
        )
    return path
