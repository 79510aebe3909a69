"""The family of benchmark charts (benchmarks/test_voyages.py): several kinds of chart, some
tuned on, the others held out from any tuning of the engine and of `auto`'s cost model.

Tuned on (the engine's constants and auto's times per pixel were set on these):
  * A winter / A summer: seaway.samples.synthetic_sea() (1900 x 2300, 30 % land in blobs, costs
    1-30; summer: mapped onto 1-2);
  * A small: synthetic_sea((300, 333)), 10^5 pixels, where the fixed costs show;
  * kara (real): the Kara Sea from GSHHG and NSIDC for Arc7 (benchmarks/real_chart.py).
Held out (never looked at while tuning):
  * B winter / B summer: seaway.samples.family.floe_sea() (2300 x 1900, 30 % land from ridged noise,
    ice in zones of constant cost 1-30 with sharp edges, leads; summer: mapped onto 1-2);
  * B small: floe_sea((333, 300));
  * sigrid (AARI-shaped): the synthetic pan-Arctic SIGRID-3 chart of tests/support/panarctic.py
    rasterised with read_sigrid3 onto 0.05 deg lat/lon pixels of the Kara Sea (270 x 1100),
    priced for Arc7;
  * sigrid CIS (real): the Canadian Ice Service's chart of 2020-11-02 (Baffin Bay, Davis
    Strait) rasterised onto 0.05 deg lat/lon pixels (300 x 600), priced for Arc7;
  * sigrid DMI (real): the Danish Meteorological Institute's chart of Cape Farewell of
    2014-04-25 on 0.01 deg lat/lon pixels (740 x 1465), Arc7: added after auto's least-cost
    rule was read off the two charts above, and held out from it;
  * game map: seaway.samples.family.game_map() (1024 x 1024, coastline of noise at three scales,
    costs 1-20);
  * maze: seaway.samples.family.maze() (1200 x 1200, channels 8 pixels wide, costs 1-5).

Voyages: 0 from the water pixel nearest one corner to the one nearest the opposite corner (the
named ends on the real Kara chart), 1..N random pairs of water pixels reached from its start
(seed 21). SEAWAY_BENCH_CHARTS (comma-separated names) and SEAWAY_BENCH_PAIRS pick fewer."""

from __future__ import annotations

import os
from dataclasses import dataclass, field

import numpy as np

import seaway
from seaway.samples import synthetic_endpoints, synthetic_sea
from seaway.samples.family import floe_sea, game_map, maze

PAIRS = int(os.environ.get("SEAWAY_BENCH_PAIRS", "8"))
SHARED = os.path.join(os.path.dirname(__file__), "..", "..", "shared", "data")
CIS = os.path.join(SHARED, "ice_charts_sigrid3", "cis_eastern_arctic", "cis_SGRDREA_20201102T.gpkg")
DMI = os.path.join(SHARED, "ice_charts_sigrid3", "dmi_greenland", "201404250420_CapeFarewell2_RIC.shp")
DMI_2013 = os.path.join(SHARED, "ice_charts_sigrid3", "dmi_greenland", "201304100920_CapeFarewell_RIC.shp")
DMI_SW = os.path.join(SHARED, "ice_charts_sigrid3", "dmi_greenland", "201405011000_SouthWest_RIC.shp")


@dataclass
class Chart:
    name: str
    kind: str
    tuned: bool
    cost: object  # ndarray (planar) or DataArray (lat/lon)
    voyages: list = field(default_factory=list)  # [(start, end)] in the chart's own points
    pixels: list = field(default_factory=list)  # the same as (row, col) pixels, for the peers

    @property
    def raster(self):
        return np.asarray(getattr(self.cost, "values", self.cost), float)


def summer(cost):
    """Winter costs 1-30 mapped onto 1-2 (open summer ice), same land."""
    return np.where(np.isfinite(cost), 1.0 + (cost - 1.0) / 29.0, np.inf)


def _nearest_water(water, rc):
    return tuple(map(int, water[np.argmin((water[:, 0] - rc[0]) ** 2 + (water[:, 1] - rc[1]) ** 2)]))


def _with_voyages(chart, corner):
    """Voyage 0 between the pixels of the largest water body nearest the `corner` pixels, then
    PAIRS random pairs of pixels reached from its start."""
    from scipy import ndimage

    labels, _ = ndimage.label(np.isfinite(chart.raster), np.ones((3, 3)))
    largest = np.bincount(labels.ravel())[1:].argmax() + 1  # the largest water body
    water = np.argwhere(labels == largest)
    prepared = seaway.prepare(chart.cost)
    s = _nearest_water(water, corner[0])
    for k in range(20):  # a start whose 5 x 5 steps reach most of the water body (not a cove)
        field = prepared.cost_field(_point(chart, s))
        reach = np.argwhere(np.isfinite(np.asarray(getattr(field, "values", field))))
        if len(reach) >= len(water) / 2:
            break
        s = tuple(map(int, water[np.random.default_rng(k).integers(len(water))]))
    e = _nearest_water(reach, corner[1])
    pick = np.random.default_rng(21).choice(len(reach), size=(PAIRS, 2), replace=False)
    chart.pixels = [(s, e)] + [(tuple(map(int, reach[a])), tuple(map(int, reach[b]))) for a, b in pick]
    chart.voyages = [(_point(chart, a), _point(chart, b)) for a, b in chart.pixels]
    return chart


def _point(chart, px):
    if not hasattr(chart.cost, "coords"):
        return px
    return float(chart.cost["lat"].values[px[0]]), float(chart.cost["lon"].values[px[1]])


def _corners(shape):
    return synthetic_endpoints(shape)


def _planar(name, kind, tuned, cost):
    return _with_voyages(Chart(name, kind, tuned, cost), _corners(cost.shape))


def _kara():
    from .real_chart import kara_chart, voyage_pixels

    made = kara_chart()
    if made is None:
        return None
    cost = made[0]
    return _with_voyages(Chart("kara (real)", "real GSHHG + NSIDC, lat/lon", True, cost), voyage_pixels(cost))


def _sigrid(path, box, name, kind):
    from seaway.ice.grids import latlon_grid
    from seaway.ice.impact import chart_impact
    from seaway.ice.sigrid import read_sigrid3

    grid = latlon_grid(*box)
    cost = chart_impact(read_sigrid3(path, grid), "Arc7")
    rows, cols = cost.shape
    return _with_voyages(Chart(name, kind, False, cost), ((rows - 1, 0), (0, cols - 1)))


def _aari(tmp):
    from support import panarctic

    path = os.path.join(tmp, "panarctic.shp")
    panarctic.write(path, cell_km=250.0)
    return _sigrid(
        path, (66.5, 80.0, 58.5, 113.5, 0.05), "sigrid (AARI-shaped)", "SIGRID-3 synthetic, lat/lon"
    )


def _real(path, box, name):
    """A real SIGRID-3 chart rasterised on lat/lon pixels (box: south, north, west, east, step
    in degrees), Arc7; None when ../shared/data is absent. Held out: CIS; DMI 2014-04-25 from
    auto's least-cost rule (read off CIS and the AARI-shaped chart); DMI 2013-04-10 and
    2014-05-01 SW from auto's short-voyage rule on prepared charts (read off the AARI-shaped,
    CIS and DMI 2014-04-25 charts)."""
    if not os.path.exists(path):
        return None
    return _sigrid(path, box, name, "SIGRID-3 real, lat/lon")


BUILDERS = {
    "A winter": lambda tmp: _planar("A winter", "synthetic recipe A", True, synthetic_sea()),
    "A summer": lambda tmp: _planar("A summer", "synthetic recipe A, summer", True, summer(synthetic_sea())),
    "A small": lambda tmp: _planar("A small", "small (10^5 px), recipe A", True, synthetic_sea((300, 333))),
    "kara (real)": lambda tmp: _kara(),
    "B winter": lambda tmp: _planar("B winter", "synthetic recipe B", False, floe_sea()),
    "B summer": lambda tmp: _planar("B summer", "synthetic recipe B, summer", False, summer(floe_sea())),
    "B small": lambda tmp: _planar("B small", "small (10^5 px), recipe B", False, floe_sea((333, 300))),
    "sigrid (AARI-shaped)": _aari,
    "sigrid CIS (real)": lambda tmp: _real(CIS, (60.0, 75.0, -75.0, -45.0, 0.05), "sigrid CIS (real)"),
    "sigrid DMI (real)": lambda tmp: _real(DMI, (58.0, 65.4, -56.65, -42.0, 0.01), "sigrid DMI (real)"),
    "sigrid DMI 2013 (real)": lambda tmp: _real(
        DMI_2013, (56.2, 63.5, -55.2, -37.3, 0.02), "sigrid DMI 2013 (real)"
    ),
    "sigrid DMI SW (real)": lambda tmp: _real(
        DMI_SW, (65.3, 70.76, -63.36, -50.0, 0.02), "sigrid DMI SW (real)"
    ),
    "game map": lambda tmp: _planar("game map", "game-map coastline", False, game_map()),
    "maze": lambda tmp: _planar("maze", "maze of narrow channels", False, maze()),
}
NAMES = [n.strip() for n in os.environ.get("SEAWAY_BENCH_CHARTS", ",".join(BUILDERS)).split(",") if n.strip()]
