"""A synthetic AARI-style winter (February) SIGRID-3 ice chart of the whole Northern Sea Route,
from the Barents and Kara Seas to the Bering Strait, written in lon/lat (EPSG:4326) as AARI
publishes its charts: rings cross the antimeridian (edges jumping +180 -> -180), land is cut out
of the ice and written as POLY_TYPE L. What each part of the chart holds and why is in
docs/user/validation.md ("The synthetic February chart"); in short:

* land: a coarse but recognisable coastline (LAND below: Novaya Zemlya, Yamal with the Gulf of
  Ob, Gydan, Taymyr with Cape Chelyuskin, Severnaya Zemlya, the New Siberian Islands, Wrangel,
  Chukotka with Cape Dezhnev, Alaska), not the GSHHG file (real data, which may be absent);
* fast ice (FA 08, SA 99, CT 92: stage unknown, as AARI's winter charts give it) in a band of
  FAST_KM along every coast, over the whole Gulf of Ob and Yenisei Gulf, and over the wide fast
  ice of the south-eastern Laptev and East Siberian Seas with the straits of the New Siberian
  Islands ("straits ... covered by thick fast ice", Moscow Times, 24 Feb 2021);
* young ice and nilas (SA 83 / SB 82) in flaw polynyas POLYNYA_KM wide off the fast ice, where
  the winter flaw polynyas open (off Yamal, Ob-Yenisei, the Laptev Sea, Chukotka);
* first-year ice by region in cells of CELL_KM (REGIONS): medium with thin in the SW Kara Sea,
  thick with medium in the NE Kara Sea and the Laptev Sea (60 % thick first-year ice on average
  in the Laptev Sea, Arctic and Antarctic Research No 4, 2017), thick first-year ice in the East
  Siberian Sea with old-ice inclusions north of 74.5 N, medium first-year ice in the southern
  Chukchi Sea; old ice north of 80 N; concentrations 9-10/10.

`write(path)` writes the shapefile; `region_at(lat, lon)` says which region's ice a point lies
in (for tests that check what a route crosses)."""

from __future__ import annotations

import numpy as np
import pyproj
import shapely

#: Lambert azimuthal equal-area on the pole, centred on the NSR (125 E): the plane the chart's
#: cells, buffers and cuts are made in (km are km there).
PLANE = "+proj=laea +lat_0=90 +lon_0=125 +datum=WGS84 +units=m"
TO_PLANE = pyproj.Transformer.from_crs("EPSG:4326", PLANE, always_xy=True)
TO_LONLAT = pyproj.Transformer.from_crs(PLANE, "EPSG:4326", always_xy=True)
CELL_KM = 125.0  # the side of the ice cells
FAST_KM = 25.0  # the fast-ice band along every coast
POLYNYA_KM = 30.0  # the width of a flaw polynya off the fast ice
SOUTH, NORTH, WEST, EAST = 64.0, 84.0, 50.0, 200.0  # the chart's box (lon east, past 180)

#: Coastlines as rings of "lon lat" (lon east, 0-360), coarse (points some 50-150 km apart).
LAND = {
    "Eurasia": (
        "50 60, 50 68, 54 68.4, 57 68.7, 58.4 70.05, 60.5 70.1, 62 69.6, 66 68.9, 66.8 69.7, "
        "66.9 71, 68.5 72.4, 70 73.5, 71.5 73.3, 72.7 72.9, 72.3 72.2, 72 71.3, 72.4 70, "
        "72.8 68.5, 73.3 67.5, 74.6 67.5, 74.6 69.5, 74.4 71, 75.2 72.4, 77.5 72.2, "
        "79.5 71.8, 80.6 71.6, 80.6 73.4, 84 73.8, 87 74.8, 91 75.6, 95 76.1, 99 76.6, "
        "101.5 77.1, 104.3 77.7, 106.5 77.2, 110 76.4, 113.5 75.7, 113 74, 110 73.6, "
        "113.5 73.5, 118 73.3, 123 73.3, 127 73.4, 129 72.8, 130 71.2, 133 71.4, 136 71.5, "
        "139 72.2, 140.7 72.9, 142.5 72.7, 146 72.3, 150 71.6, 154 71, 157 70.9, 161 69.6, "
        "165 69.7, 168 69.9, 170.6 70.1, 174 69.9, 177 69.5, 180.6 68.9, 183 68.4, 186 67.5, "
        "188 67, 189.6 66.4, 190.35 66.07, 189.8 65.5, 187 64.3, 186 64, 186 60"
    ),
    "Novaya Zemlya": (
        "53 70.8, 57.8 70.65, 57 72.5, 62 75, 68.6 76.55, 68.5 77.1, 60 76.8, 55 75.5, 52 72.5"
    ),
    "Severnaya Zemlya": "99.5 78.3, 105.3 78.15, 105.8 79.4, 101 80.6, 97 81.2, 92 80.8, 94 79.4",
    "Bolshoy Lyakhovsky": "139.5 73.3, 143.5 73.2, 143 73.9, 140 73.9",
    "Kotelny and New Siberia": "137.5 75, 140.5 74.45, 145 74.8, 150 74.8, 150 75.3, 146 75.9, 142 76.2, 138 76",
    "Wrangel": "178.3 71.2, 180 70.8, 182.6 70.9, 182.4 71.5, 180 71.6, 178.7 71.5",
    "Alaska": (
        "191.9 65.6, 193.9 66.25, 196 66.6, 193.2 68.35, 193.8 68.9, 197 70.2, 200 70.7, 200 60, 191.9 60"
    ),
}
#: Fast ice beyond the coastal band: the Gulf of Ob and Yenisei Gulf (closed gulfs), the wide
#: fast ice of the south-eastern Laptev and East Siberian Seas, over the straits of the New
#: Siberian Islands (the "straits ... covered by thick fast ice" of Feb 2021).
WIDE_FAST = [
    [(71.5, 66.5), (75.5, 66.5), (75.5, 72.5), (71.5, 72.5)],
    [(79.5, 70.5), (83, 70.5), (83, 72.5), (79.5, 72.5)],
    [(129, 71), (137.5, 71), (139, 74.3), (145, 74.3), (152, 74.1), (160, 71.0), (129, 72.3)],
]
#: Where flaw polynyas open off the fast ice: (west, east, south, north) in lon east / lat.
POLYNYAS = [
    (66.0, 71.0, 68.5, 73.2),
    (74.0, 87.0, 72.8, 75.5),
    (104.0, 138.0, 72.5, 78.5),
    (183.0, 191.0, 66.0, 69.0),
]

FAST = dict(POLY_TYPE="I", CT="92", CA=None, SA="99", CB=None, SB=None, FA="08", FB=None)
YOUNG = dict(POLY_TYPE="I", CT="92", CA="07", SA="83", CB="03", SB="82", FA=None, FB=None)


def _ice(ct, ca, sa, cb, sb):
    return dict(POLY_TYPE="I", CT=ct, CA=ca, SA=sa, CB=cb, SB=sb, FA=None, FB=None)


#: (name, test on (lon east, lat), SIGRID-3 attributes): the first region whose test holds.
REGIONS = [
    ("old ice", lambda lo, la: la >= 80.0, _ice("92", "08", "95", "02", "93")),
    ("Barents Sea", lambda lo, la: lo < 57.5, _ice("91", "07", "87", "03", "85")),
    ("SW Kara Sea", lambda lo, la: lo < 75.0 and la < 74.0, _ice("92", "06", "91", "04", "87")),
    ("NE Kara Sea", lambda lo, la: lo < 105.0, _ice("92", "04", "93", "06", "91")),
    ("Laptev Sea", lambda lo, la: lo < 140.0, _ice("92", "06", "93", "04", "91")),
    (
        "northern East Siberian Sea",
        lambda lo, la: lo < 180.0 and la >= 74.5,
        _ice("92", "02", "95", "08", "93"),
    ),
    ("East Siberian Sea", lambda lo, la: lo < 180.0, _ice("92", "08", "93", "02", "91")),
    ("northern Chukchi Sea", lambda lo, la: la >= 70.0, _ice("92", "06", "93", "04", "91")),
    ("Chukchi Sea", lambda lo, la: la >= 66.3, _ice("92", "07", "91", "03", "87")),
    ("Bering Strait", lambda lo, la: True, _ice("91", "06", "87", "04", "85")),
]
NAMES = ["POLY_TYPE", "CT", "CA", "SA", "CB", "SB", "FA", "FB"]


def region(lon: float, lat: float) -> tuple[str, dict]:
    """(name, attributes) of the first-year (or old) ice region at lon (east, any), lat."""
    lo = float(lon) % 360.0
    for name, test, attrs in REGIONS:
        if test(lo, lat):
            return name, attrs
    raise AssertionError("unreachable: the last region holds everywhere")


def _ring(text):
    """A ring of "lon lat, lon lat, ..." as (lon, lat) pairs."""
    return [tuple(float(v) for v in pair.split()) for pair in text.split(",")]


def _plane(lonlat, step_deg=0.05):
    """A lon/lat ring as a polygon in the PLANE, densified in lon/lat first (edges follow
    parallels and meridians, as a chart in degrees draws them)."""
    ring = shapely.segmentize(shapely.Polygon(lonlat), step_deg)
    xy = np.asarray(ring.exterior.coords)
    return shapely.make_valid(shapely.Polygon(np.column_stack(TO_PLANE.transform(xy[:, 0], xy[:, 1]))))


def _to_lonlat(geom):
    return shapely.transform(geom, lambda xy: np.column_stack(TO_LONLAT.transform(xy[:, 0], xy[:, 1])))


def _box(west, east, south, north):
    return _plane([(west, south), (east, south), (east, north), (west, north)], 0.25)


def build():
    """(polygons in the PLANE, attribute dicts, names): the chart's features, land last."""
    land = {name: _plane(_ring(text)) for name, text in LAND.items()}
    land_all = shapely.unary_union(list(land.values()))
    chart = _box(WEST, EAST, SOUTH, NORTH).difference(land_all)
    band = shapely.buffer(land_all, FAST_KM * 1000.0)
    fast = shapely.unary_union([band, *(_plane(p) for p in WIDE_FAST)]).intersection(chart)
    near = shapely.buffer(fast, POLYNYA_KM * 1000.0).difference(fast)
    boxes = shapely.unary_union([_box(*b) for b in POLYNYAS])
    young = near.intersection(boxes).intersection(chart)
    pack = chart.difference(fast).difference(young)
    geoms, attrs, names = [], [], []
    for g, a, n in ((fast, FAST, "fast ice"), (young, YOUNG, "flaw polynya")):
        for part in _cells(g):
            geoms.append(part)
            attrs.append(a)
            names.append(n)
    for part in _cells(pack):
        c = part.representative_point()
        lon, lat = TO_LONLAT.transform(c.x, c.y)
        name, a = region(lon, lat)
        geoms.append(part)
        attrs.append(a)
        names.append(name)
    for name, g in land.items():
        geoms.append(g.intersection(_box(WEST - 1, EAST + 1, SOUTH - 1, 89.0)))
        attrs.append(dict.fromkeys(NAMES) | {"POLY_TYPE": "L"})
        names.append(name)
    return geoms, attrs, names


def _cells(geom):
    """`geom` cut into the CELL_KM squares of the plane (each a polygon or multipolygon)."""
    x0, y0, x1, y1 = geom.bounds
    side = CELL_KM * 1000.0
    out = []
    for x in np.arange(np.floor(x0 / side) * side, x1, side):
        for y in np.arange(np.floor(y0 / side) * side, y1, side):
            part = shapely.box(x, y, x + side, y + side).intersection(geom)
            part = shapely.union_all([p for p in shapely.get_parts(part) if p.geom_type == "Polygon"])
            if not part.is_empty and part.area > 1e6:
                out.append(part)
    return out


def write(path):
    """Write the chart as an ESRI shapefile in lon/lat (EPSG:4326); returns the feature names
    (region, "fast ice", "flaw polynya" or the land's name) in the file's order."""
    import pyogrio.raw

    geoms, attrs, names = build()
    written = [_to_lonlat(shapely.segmentize(g, 10_000.0)) for g in geoms]
    wkb = shapely.to_wkb([shapely.MultiPolygon(list(shapely.get_parts(g))) for g in written])
    data = [np.array([a[k] for a in attrs], dtype=object) for k in NAMES]
    pyogrio.raw.write(str(path), wkb, data, NAMES, geometry_type="MultiPolygon", crs="EPSG:4326")
    return names


def point(lat: float, lon: float):
    """The point lat, lon in the PLANE."""
    return shapely.Point(*TO_PLANE.transform(float(lon), float(lat)))


def feature_at(lat: float, lon: float, geoms=None, names=None) -> str:
    """The name of the chart's feature at lat, lon (as write() returns them), from the polygons
    in the plane (independent of seaway's reader); "" off the chart."""
    if geoms is None:
        geoms, _, names = build()
    p = point(lat, lon)
    for g, n in zip(geoms, names):
        if g.covers(p):
            return n
    return ""
