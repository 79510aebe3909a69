"""Chart polygons made correct in the grid's CRS before rasterising: rings that cross the
antimeridian (edges jumping +180 -> -180), rings around a pole, holes, multi-part polygons and
invalid rings (self-intersections, wrong winding).

How (libraries do the geometry):
* geographic charts (lon/lat): each ring that jumps across +-180 or winds around a pole is
  cut at the antimeridian by the `antimeridian` package (a pole-enclosing ring is closed over
  the pole of its hemisphere), self-intersecting rings are repaired by shapely.make_valid, and
  the rings of a feature are combined by the even-odd rule (holes, islands in holes).
* projected charts: shapely.make_valid in the chart's own CRS, where the rings are planar.
* long edges are densified (shapely.segmentize) in the chart's CRS before pyproj moves the
  vertices to the grid's CRS, so an edge keeps the course it has in the file; polygons moved
  to lon/lat from a projected chart are cut at the antimeridian the same way.
* lat/lon grids reaching past +-180 (e.g. 160..200 E) get copies shifted by 360 degrees.
Edges are straight in the chart's CRS (as GIS software draws them)."""

from __future__ import annotations

import warnings

import numpy as np

#: Densify edges longer than this before reprojecting: degrees, or metres (projected charts).
SEGMENT_DEG = 0.1
SEGMENT_M = 10_000.0


def _crs(value):
    import pyproj

    return pyproj.CRS.from_user_input(value)


def _winding_deg(ring) -> float:
    """Net longitude travelled around a lon/lat ring: +-360 if it encloses a pole, else 0."""
    lon = np.asarray(ring.coords)[:, 0]
    return float(np.sum((np.diff(lon) + 180.0) % 360.0 - 180.0))


def _jumps(ring) -> bool:
    lon = np.asarray(ring.coords)[:, 0]
    return bool(len(lon) > 1 and np.abs(np.diff(lon)).max() > 180.0)


def _ring_region(ring):
    """The region one lon/lat ring encloses, valid and within -180..180."""
    import antimeridian
    import shapely

    poly = shapely.Polygon(ring)
    winding = _winding_deg(ring)
    if _jumps(ring) or abs(winding) > 180:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # winding corrections are what we ask for
            if abs(winding) > 180:  # around a pole: the pole of the ring's hemisphere
                north = np.asarray(ring.coords)[:, 1].mean() >= 0
                poly = antimeridian.fix_polygon(poly, force_north_pole=north, force_south_pole=not north)
            else:
                poly = antimeridian.fix_polygon(poly, fix_winding=True)
    return poly if poly.is_valid else _polygonal(shapely.make_valid(poly))


def _polygonal(geom):
    """The (multi)polygon parts of a geometry (make_valid may add lines and points)."""
    import shapely

    parts = [p for p in shapely.get_parts(geom) if p.geom_type in ("Polygon", "MultiPolygon")]
    return shapely.unary_union(parts) if parts else shapely.Polygon()


def fix_lonlat(geom):
    """A lon/lat (multi)polygon as read from a chart -> a valid one within -180..180.

    Each ring is made a region on its own, and the regions are combined by the even-odd rule
    (symmetric difference): a hole is any ring inside another, whatever its winding and
    however the reader grouped the rings (GDAL groups them by planar lon/lat winding and
    containment, which rings across +-180 defeat)."""
    import shapely

    if geom is None or geom.is_empty:
        return shapely.Polygon()
    rings = [
        r
        for p in shapely.get_parts(geom)
        if p.geom_type == "Polygon"
        for r in (p.exterior, *p.interiors)
        if len(r.coords) >= 4
    ]
    regions = [g for g in (_ring_region(r) for r in rings) if not g.is_empty]
    if not regions:
        return shapely.Polygon()
    out = regions[0]
    for g in regions[1:]:
        out = shapely.symmetric_difference(out, g)
    return _polygonal(out)


def fix_planar(geom):
    """A valid polygon for a planar geometry (repaired with shapely.make_valid; empty for None)."""
    import shapely

    if geom is None or geom.is_empty:
        return shapely.Polygon()
    return geom if geom.is_valid else _polygonal(shapely.make_valid(geom))


def _move(geoms, src, dst):
    import pyproj
    import shapely

    tr = pyproj.Transformer.from_crs(src, dst, always_xy=True)
    return shapely.transform(geoms, lambda xy: np.column_stack(tr.transform(xy[:, 0], xy[:, 1])))


def to_grid_crs(geoms, src_crs, grid_crs):
    """Chart polygons (array of shapely geometries in `src_crs`) -> valid polygons in
    `grid_crs`, plus the number that needed repair (invalid, across +-180 or around a pole)."""
    import shapely

    src, dst = _crs(src_crs), _crs(grid_crs)
    geoms = np.asarray(geoms, dtype=object)
    if src.is_geographic:
        before = shapely.to_wkb(geoms)
        out = np.array([fix_lonlat(g) for g in geoms], dtype=object)
        repaired = int(sum(a != b for a, b in zip(before, shapely.to_wkb(out))))
        if src.equals(dst):
            return out, repaired
        out = shapely.segmentize(out, SEGMENT_DEG)
    else:
        out = np.array([fix_planar(g) for g in geoms], dtype=object)
        repaired = int(sum(a is not b for a, b in zip(geoms, out)))
        if src.equals(dst):
            return out, repaired
        out = shapely.segmentize(out, SEGMENT_M)
    moved = _move(out, src, dst)
    if dst.is_geographic:  # reprojected rings may now cross +-180 or wind around a pole
        return np.array([fix_lonlat(g) for g in moved], dtype=object), repaired
    return np.array([fix_planar(g) for g in moved], dtype=object), repaired


def wrap_copies(geoms, west: float, east: float):
    """(geometry, index) pairs for a lat/lon grid spanning west..east: each polygon, plus
    copies shifted by +-360 degrees where the grid reaches past -180 or 180."""
    import shapely

    shifts = [0.0] + ([360.0] if east > 180 else []) + ([-360.0] if west < -180 else [])
    out = []
    for i, g in enumerate(geoms):
        if g is None or g.is_empty:
            continue
        for s in shifts:
            out.append((g if s == 0 else shapely.transform(g, lambda xy, s=s: xy + [s, 0.0]), i))
    return out
