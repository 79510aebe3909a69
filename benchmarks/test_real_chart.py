"""The per-voyage benchmark (test_voyages.py) on a chart of real data: the Kara Sea on
2021-12-31 from the GSHHG land mask (1 arc-minute) and NSIDC's sea-ice concentration made Arc7
costs (real_chart.py), 810 x 3300 lat/lon pixels; the voyage from the Kara Gate to the western
approach of the Vilkitsky Strait and 8 random pairs of connected water pixels. Skipped when
../shared/data is absent.

    pytest benchmarks/test_real_chart.py -s -p no:randomly
"""

import numpy as np
import pytest

import seaway

from .conftest import VOYAGES
from .real_chart import kara_chart, voyage_pixels
from .test_voyages import RANDOM_PAIRS, time_voyage

pytest.importorskip("skimage.graph")


@pytest.fixture(scope="module")
def kara():
    made = kara_chart()
    if made is None:
        pytest.skip("the real data (../shared/data: land, sea_ice_concentration) are absent")
    cost, notes = made
    prepared = seaway.prepare(cost)
    st = prepared.prepare_landmarks(8)
    VOYAGES.setdefault("notes", []).append(
        f"kara (real): {cost.shape[0]} x {cost.shape[1]} pixels, "
        f"{np.isfinite(cost.values).mean():.0%} water, 8 landmarks in {st['seconds']:.2f} s; "
        + "; ".join(notes)
    )
    lat, lon = cost["lat"].values, cost["lon"].values

    def point(px):
        return float(lat[px[0]]), float(lon[px[1]])

    start, end = voyage_pixels(cost)
    reach = np.argwhere(np.isfinite(prepared.cost_field(point(start)).values))
    pick = np.random.default_rng(21).choice(len(reach), size=(RANDOM_PAIRS, 2), replace=False)
    pairs = [(start, end)] + [(tuple(reach[a]), tuple(reach[b])) for a, b in pick]
    return cost, prepared, [(point(a), point(b)) for a, b in pairs]


@pytest.mark.parametrize("voyage", range(1 + RANDOM_PAIRS))
def test_real_chart_voyage(kara, voyage):
    cost, prepared, voyages = kara
    s, e = voyages[voyage]
    time_voyage("kara (real)", voyage, cost, prepared, s, e)
