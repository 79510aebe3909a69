"""A season's concentration in its own units (seaway.ice.seasonvars): CF sea_ice_area_fraction
as a fraction, in % or in tenths ("0.1", as seaway.samples.kara_sea() gives it) becomes CT in
tenths; a chart's stage_of_development becomes SA; unknown units and values outside their range
are refused naming the fix. The Kara sample as a one-day season reaches what the chart does."""

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway.ice.seasongrid import as_season
from seaway.samples import kara_sea

DAY = np.datetime64("2026-03-01")


def _season(values, units):
    frac = xr.DataArray(
        np.asarray(values, float).reshape(1, 1, -1),
        dims=("time", "y", "x"),
        attrs={"standard_name": "sea_ice_area_fraction", "units": units},
    )
    thick = xr.DataArray(np.full(frac.shape, 0.5), dims=frac.dims, attrs={"units": "m"})
    return xr.Dataset({"conc": frac, "thickness": thick}, coords={"time": [DAY]})


@pytest.mark.parametrize(
    "values,units",
    [([0.0, 0.45, 1.0], "1"), ([0, 45, 100], "%"), ([0.0, 4.5, 10.0], "0.1"), ([0, 0.45, 1], None)],
)
def test_a_concentration_in_its_units_becomes_tenths(values, units):
    ds = _season(values, units)
    if units is None:
        del ds["conc"].attrs["units"]
    np.testing.assert_allclose(as_season(ds)["CT"].values.ravel(), [0.0, 4.5, 10.0])


def test_round_off_is_clipped_and_other_units_refused():
    np.testing.assert_allclose(as_season(_season([-1e-6, 1 + 1e-6], "1"))["CT"].values.ravel(), [0.0, 10.0])
    with pytest.raises(
        seaway.ChartError, match=r"units 'furlongs'.* give units '1' \(a fraction\), '%' or '0.1'"
    ):
        as_season(_season([0.5], "furlongs"))
    with pytest.raises(seaway.ChartError, match=r"CT holds 1 value\(s\) outside its range.*other units"):
        as_season(_season([0.0, 45.0], "1"))  # percent labelled as a fraction: refused, not clipped


def test_the_kara_sample_as_a_one_day_season_reaches_what_the_chart_does(tmp_path):
    path = tmp_path / "kara.nc"
    chart = kara_sea()
    chart.expand_dims(time=[DAY]).to_netcdf(path)
    season = seaway.open_season(str(path))
    ds = season.grid.ds
    np.testing.assert_array_equal(ds["CT"].values[0], chart["sea_ice_concentration"].values)  # tenths
    stage = chart["stage_of_development"].values
    np.testing.assert_array_equal(ds["SA"].values[0], np.where(stage == 55, np.nan, stage))
    gulf_of_ob = (71.7026, 67.2826)
    opened = seaway.open_chart("kara")
    for limit, reached in ((False, 2048938), (True, 125057)):
        field = season.arrival_field(gulf_of_ob, vessel="Arc7", concentration_limit=limit)
        same = opened.arrival_field(gulf_of_ob, vessel="Arc7", speed_kn=12, concentration_limit=limit)
        assert int(np.isfinite(field).sum()) == int(np.isfinite(same).sum()) == reached
