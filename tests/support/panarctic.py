"""A synthetic pan-Arctic SIGRID-3 chart whose true polygons are known in EPSG:3413 (NSIDC polar
stereographic north), written in lon/lat (EPSG:4326) as AARI publishes its charts: square cells
of the 3413 plane, so rings cross the antimeridian (edges jumping +180 -> -180) and one cell
encloses the North Pole; land cut out of the cells (multi-part polygons); holes (one filled by
an open-water polygon, one left uncharted, one straddling +-180); one self-intersecting
(bow-tie) ring. Ice and land are plausible for the Northern Sea Route: thin and medium
first-year ice in the Kara and Laptev Seas, old ice (impassable for Arc7) near the pole,
Novaya Zemlya, Yamal, Taymyr and Severnaya Zemlya as land, so that a route exists from the Kara
Gate (70.4 N 58.6 E) to the Vilkitsky Strait (77.7 N 104.0 E).

Used by tests/test_panarctic.py and benchmarks/test_rasterise.py, independently of the reader:
`truth` are the polygons in EPSG:3413 that the file's rings trace."""

from __future__ import annotations

import numpy as np
import pyproj
import shapely

TO_LONLAT = pyproj.Transformer.from_crs("EPSG:3413", "EPSG:4326", always_xy=True)
TO_POLAR = pyproj.Transformer.from_crs("EPSG:4326", "EPSG:3413", always_xy=True)
RADIUS_M = 3_300_000.0  # the chart covers a disc of this radius around the pole (about 60 N)
#: (lon, lat) outlines of land, densified in lon/lat (edges follow parallels and meridians).
LAND = {
    "Siberia": [
        (40, 60),
        (140, 60),
        (140, 69.8),
        (85, 69.8),
        (85, 77.3),
        (115, 77.3),
        (115, 69.8),
        (72, 69.8),
        (72, 72.5),
        (67, 72.5),
        (67, 69.8),
        (40, 69.8),
    ],
    "Novaya Zemlya": [
        (53, 70.8),
        (58, 70.7),
        (57, 72.5),
        (62, 75),
        (69, 76.5),
        (68.5, 77.1),
        (60, 76.8),
        (55, 75.5),
        (52, 72.5),
    ],
    "Severnaya Zemlya": [(95, 78.2), (107, 78.2), (107, 81), (95, 81)],
}


def _polar(lonlat, step_deg=0.1):
    ring = shapely.segmentize(shapely.Polygon(lonlat), step_deg)
    xy = np.asarray(ring.exterior.coords)
    return shapely.Polygon(np.column_stack(TO_POLAR.transform(xy[:, 0], xy[:, 1])))


def _disc(x, y, r, n=64):
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    return shapely.Polygon(np.column_stack([x + r * np.cos(t), y + r * np.sin(t)]))


def _to_lonlat(geom):
    return shapely.transform(geom, lambda xy: np.column_stack(TO_LONLAT.transform(xy[:, 0], xy[:, 1])))


def _ice(lon, lat, k):
    """Attributes of an ice cell centred at lon, lat (k: cell number, for variety)."""
    if lat >= 84:
        return dict(POLY_TYPE="I", CT="92", CA="90", SA="95", CB="-9", SB="98")  # old ice
    if 50 <= lon <= 140:  # Kara and Laptev Seas: thin first-year
        return dict(POLY_TYPE="I", CT="91" if k % 2 else "80", CA=None, SA="87", CB=None, SB="81")
    return dict(POLY_TYPE="I", CT="91", CA="60", SA="91", CB="30", SB="87")


def build(cell_km=600.0, seed=0):
    """(truth polygons in EPSG:3413 metres, lon/lat geometries to write, attribute dicts)."""
    half = cell_km * 1000.0
    offset = half / 3.0  # the pole lies inside a cell, not on a corner
    n = int(np.ceil(RADIUS_M / half)) + 1
    disc = _disc(0.0, 0.0, RADIUS_M, 720)
    land = {name: _polar(v) for name, v in LAND.items()}
    land_all = shapely.unary_union(list(land.values()))
    # Holes: around (lat 88, lon 10) filled by a polynya (open water), around (lat 87, lon 100)
    # uncharted, and one across the antimeridian at lat 75, uncharted.
    polynya = _disc(*TO_POLAR.transform(10.0, 88.0), 60_000.0)
    gap = _disc(*TO_POLAR.transform(100.0, 87.0), 60_000.0)
    gap180 = _disc(*TO_POLAR.transform(180.0, 75.0), 90_000.0)
    bowtie_xy = np.array(TO_POLAR.transform([150, 160, 150, 160], [71.0, 72.0, 72.0, 71.0])).T
    bowtie = shapely.Polygon(bowtie_xy)  # self-intersecting: two triangles
    bowtie_valid = shapely.make_valid(bowtie)
    cut = shapely.unary_union([land_all, polynya, gap, gap180, bowtie_valid])
    truth, attrs = [], []
    for i in range(-n, n):
        for j in range(-n, n):
            x0, y0 = i * half + offset, j * half + offset
            cell = shapely.box(x0, y0, x0 + half, y0 + half).intersection(disc).difference(cut)
            if cell.is_empty or cell.area < 1e6:
                continue
            cell = shapely.segmentize(cell, 20_000.0)
            c = cell.representative_point()
            lon, lat = TO_LONLAT.transform(c.x, c.y)
            truth.append(cell)
            attrs.append(_ice(lon % 360, lat, len(truth)))
    for name, g in land.items():
        truth.append(shapely.segmentize(g.intersection(disc), 20_000.0))
        attrs.append(dict(POLY_TYPE="L", CT=None, CA=None, SA=None, CB=None, SB=None))
    truth.append(shapely.segmentize(polynya, 20_000.0))
    attrs.append(dict(POLY_TYPE="W", CT="00", CA=None, SA=None, CB=None, SB=None))
    truth.append(bowtie_valid)
    attrs.append(dict(POLY_TYPE="I", CT="40", CA=None, SA="81", CB=None, SB=None))
    written = [_to_lonlat(g) for g in truth]
    closed = np.vstack([bowtie_xy, bowtie_xy[:1]])  # the invalid ring as drawn, densified
    dense = np.vstack([np.linspace(a, b, 20, endpoint=False) for a, b in zip(closed[:-1], closed[1:])])
    written[-1] = _to_lonlat(shapely.Polygon(dense))
    return truth, written, attrs


def write(path, cell_km=600.0):
    """Write the chart as an ESRI shapefile (or any driver the extension names); returns the
    truth polygons (EPSG:3413) in the file's feature order."""
    import pyogrio.raw

    truth, written, attrs = build(cell_km)
    names = ["POLY_TYPE", "CT", "CA", "SA", "CB", "SB"]
    data = [np.array([a[k] for a in attrs], dtype=object) for k in names]
    wkb = shapely.to_wkb([shapely.MultiPolygon(list(shapely.get_parts(g))) for g in written])
    pyogrio.raw.write(str(path), wkb, data, names, geometry_type="MultiPolygon", crs="EPSG:4326")
    return truth


def agreement(ds, grid, truth, n=4000, seed=1):
    """Fraction of `n` sampled pixel centres whose assigned polygon covers the centre in
    EPSG:3413 (or, for pixels off the chart, that no polygon covers), and the sample size."""
    rng = np.random.default_rng(seed)
    ny, nx = grid.shape
    r, c = rng.integers(0, ny, n), rng.integers(0, nx, n)
    x, y = grid.x[c] * grid.scale, grid.y[r] * grid.scale
    if not grid.geographic:
        x, y = pyproj.Transformer.from_crs(grid.crs, "EPSG:4326", always_xy=True).transform(x, y)
    px, py = TO_POLAR.transform(x, y)
    points = shapely.points(px, py)
    index = ds["polygon"].values[r, c]
    tree = shapely.STRtree(truth)
    covering = tree.query(points, predicate="intersects")
    covered = np.zeros(n, bool)
    covered[covering[0]] = True
    ok = np.where(index >= 0, False, ~covered)
    for i in np.unique(index[index >= 0]):
        sel = index == i
        ok[sel] = shapely.intersects(truth[i], points[sel])
    return float(ok.mean()), n
