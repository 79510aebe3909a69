"""Small synthetic SIGRID-3 shapefiles in lon/lat (EPSG:4326), as the real charts are written:
text codes, -9 where an attribute does not apply (used by ice/test_forms.py, cli/test_cli_ends.py,
ice/test_noroute.py, output/test_map_content.py)."""

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


def write_fast_channel(path, fast_cuts=()):
    """AARI's winter shape at 60-80 E: land at 70-71 N and 74-75 N; between them open water at
    60-63 E and 77-80 E and fast ice of unknown stage at 63-77 E (FA 08, SA 99, CT 92, as AARI
    codes it), in one polygon or cut at the longitudes `fast_cuts`."""
    import shapely

    fast = {"POLY_TYPE": "I", "CT": "92", "SA": "99", "FA": "08"}
    edges = [63, *fast_cuts, 77]
    rows = [
        (shapely.box(60, 70, 80, 71), {"POLY_TYPE": "L"}),
        (shapely.box(60, 74, 80, 75), {"POLY_TYPE": "L"}),
        (shapely.box(60, 71, 63, 74), {"POLY_TYPE": "W", "CT": "00"}),
        (shapely.box(77, 71, 80, 74), {"POLY_TYPE": "W", "CT": "00"}),
    ] + [(shapely.box(w, 71, e, 74), fast) for w, e in zip(edges, edges[1:])]
    return write_chart(path, rows)
