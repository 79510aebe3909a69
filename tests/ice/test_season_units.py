"""A season on a planar grid prices its steps in hours per km, so its y/x coordinates must be
lengths in km: metres are converted, coordinates without units are taken as km and the route
says so, other units are refused naming the fix."""

import numpy as np
import pytest

from seaway.icenav.season import route_season
from support.seasons import planar_season

KN = 1.852
#: Open water at 12 kn, medium first-year ice at 3 kn (WMO stage codes).
TABLE = {55: 12.0, 91: 3.0}


def _season(dx, units=None):
    stage = np.full((2, 10, 30), 55)
    stage[:, 3:, 10:12] = 91  # a band of ice across the route, open along rows 0-2
    ds = planar_season(stage, hours=[0.0, 48.0], dx=dx)
    if units is not None:
        for c in ("y", "x"):
            ds[c].attrs.update(units=units, standard_name=f"projection_{c}_coordinate")
    return ds


def _route(ds):
    return route_season(ds, (5, 0), (5, 29), speed=TABLE, concentration_limit=False)


def test_a_season_in_metres_routes_as_the_same_season_in_km():
    km, m = _route(_season(10.0, "km")), _route(_season(10_000.0, "m"))
    assert m.cost == pytest.approx(km.cost, rel=1e-12)
    assert np.array_equal(m.pixels, km.pixels)
    # 290 km at 12 kn if the band is crossed at 3 kn for 20 km, or the detour: at most that.
    h = float(np.float32(1 / (12 * KN)))
    assert km.cost <= 270 * h + 20 * float(np.float32(1 / (3 * KN))) + 1e-9
    assert km.cost >= 290 * h - 1e-9  # no route is shorter than the straight 290 km in open water
    assert km.assumptions == () and m.assumptions == ()


def test_coordinates_without_units_are_taken_as_km_and_the_route_says_so():
    r = _route(_season(10.0))
    assert r.cost == pytest.approx(_route(_season(10.0, "km")).cost, rel=1e-12)
    said = (
        "the season's y and x coordinates have no units: taken as km (set the units attribute to 'm' or 'km')"
    )
    assert said in r.assumptions


def test_coordinates_in_other_units_are_refused_naming_the_fix():
    with pytest.raises(ValueError, match=r"'pixels': give planar coordinates in a length \('m' or 'km'\)"):
        _route(_season(10.0, "pixels"))
