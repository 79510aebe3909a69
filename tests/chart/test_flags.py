"""CF flags, valid ranges and coordinates are never costs: flagged land is land, other flags are
impassable, dimensions named lat/lon need values; a concentration-only chart becomes an ice chart
with its stage assumption said; projected charts take and give lat/lon."""

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway import open_chart
from seaway.chart.flags import flags_out
from seaway.cli import main
from seaway.errors import ChartError
from seaway.ice.concentration import concentration_chart

NSIDC = ("sea_ice_concentration", "seaice_conc_daily_nh_20211231_f17_v04r00.nc")
ROMS = ("ocean_model", "metno_ROMS_Arctic20_1to5Feb_2016.nc")


def _packed_chart(tmp_path):
    """A 9 x 9 concentration in packed uint8 (scale 0.01) as NSIDC writes it: a wall of 'land'
    flags (254) down column 4 except a gap at row 8, one 'pole_hole' (251) pixel."""
    raw = np.full((9, 9), 50, np.uint8)  # 0.5 everywhere
    raw[:8, 4] = 254
    raw[0, 0] = 251
    da = xr.DataArray(
        raw * 0.01,
        dims=("y", "x"),
        name="conc",
        attrs={
            "standard_name": "sea_ice_area_fraction",
            "units": "1",
            "flag_values": np.array([251, 252, 253, 254], np.uint8),
            "flag_meanings": "pole_hole lakes coastal land_mask",
            "valid_range": np.array([0, 100], np.uint8),
        },
    )
    da.encoding.update(scale_factor=0.01, dtype="uint8", _FillValue=np.uint8(255))
    path = tmp_path / "packed.nc"
    da.to_dataset().to_netcdf(path)
    return path


def test_flags_in_packed_units_become_land_and_impassable(tmp_path):
    da = xr.open_dataset(_packed_chart(tmp_path))["conc"]
    assert np.isclose(float(da[0, 4]), 2.54)  # decoded, but the attributes are still packed
    f = flags_out(da)
    assert f.land.sum() == 8 and f.land[:8, 4].all()
    assert np.isnan(f.values.values[0, 0]) and np.isnan(f.values.values[:8, 4]).all()
    assert float(f.values[3, 3]) == pytest.approx(0.5)
    assert f.notes == [
        "conc: 1 pixels flagged pole_hole (2.51) are impassable",
        "conc: 8 pixels flagged land_mask (2.54) are land",
    ]


def test_route_on_a_flagged_dataarray_goes_round_the_flagged_land(tmp_path):
    da = xr.open_dataset(_packed_chart(tmp_path))["conc"]
    r = seaway.route(da, (2, 2), (2, 6), neighbourhood=3)
    assert not any(c == 4 and row < 8 for row, c in r.pixels)  # never through the flagged wall
    # The same as routing the clean values with the flags as land: 0.5 per unit length, via row 8.
    clean = np.full((9, 9), 0.5)
    land = np.zeros((9, 9), bool)
    land[:8, 4] = True
    clean[0, 0] = np.inf
    ref = seaway.route(clean, (2, 2), (2, 6), land=land, neighbourhood=3)
    assert r.cost == pytest.approx(ref.cost, rel=1e-12)


def test_values_outside_valid_range_are_impassable():
    da = xr.DataArray(
        np.array([[0.2, 7.0], [0.3, 0.4]]),
        dims=("y", "x"),
        name="c",
        attrs={"valid_min": 0.0, "valid_max": 1.0},
    )
    f = flags_out(da)
    assert np.isnan(f.values.values[0, 1]) and f.land is None
    assert f.notes == ["c: 1 pixels outside its valid range 0..1 are impassable"]


def test_bit_field_flags_are_refused():
    da = xr.DataArray(
        np.zeros((2, 2)),
        dims=("y", "x"),
        name="qa",
        attrs={"flag_masks": np.array([1, 2, 4]), "flag_meanings": "a b c"},
    )
    with pytest.raises(ValueError, match="bit field of flags .* choose a data variable"):
        flags_out(da)


def test_lat_lon_dimensions_without_values_are_refused():
    da = xr.DataArray(np.ones((4, 5)), dims=("lat", "lon"))
    with pytest.raises(ValueError, match=r"dimension 'lat' has no coordinate values.*assign_coords"):
        seaway.route(da, (0, 0), (3, 4))


def test_concentration_chart_states_its_assumption():
    conc = xr.DataArray(
        np.array([[0.0, 0.1, 0.15], [0.55, 1.0, np.nan]]),
        dims=("y", "x"),
        name="aice",
        attrs={"standard_name": "sea_ice_area_fraction"},
    )
    ds, assumed = concentration_chart(conc, stage=87)
    np.testing.assert_array_equal(ds.CT.values[0], [0, 0, 2])  # 0.15 is ice: 1.5 tenths -> 2
    np.testing.assert_array_equal(ds.CT.values[1, :2], [6, 10])
    np.testing.assert_array_equal(np.isnan(ds.SA.values), [[True, True, False], [False, False, True]])
    assert ds.SA.values[1, 1] == 87
    assert "thin first-year ice (WMO stage 87), an assumption" in assumed[0]
    assert assumed[-1] == "aice: 1 pixels of no concentration are unknown ice (impassable)"
    with pytest.raises(ValueError, match="not a WMO stage of development code; give one, e.g. 93"):
        concentration_chart(conc, stage=12)


@pytest.mark.needs_data(*NSIDC)
def test_nsidc_concentration_is_refused_as_a_cost_and_read_as_an_ice_chart(shared_data):
    path = str(shared_data.joinpath(*NSIDC))
    unpriced = open_chart(path, variable="cdr_seaice_conc")  # opened as ice; priced only for a class
    with pytest.raises(ChartError, match="is a sea-ice concentration .* give --vessel CLASS"):
        unpriced.cost  # noqa: B018
    with pytest.raises(ChartError, match="is a sea-ice concentration .* give --vessel CLASS"):
        unpriced.route((70.3, 66.0), (72.9, 74.0))
    data = open_chart(path, vessel="Arc7")
    assert data.projection is not None and "3411" in data.projection.crs.to_string()
    assert "thick first-year ice (WMO stage 93), an assumption" in data.notes[0]
    assert "63707 pixels flagged land_mask (2.54) are land" in " ".join(data.notes)
    land = data.land.values
    assert land.sum() == 665 + 4561 + 63707  # lakes, coast and land flags
    assert data.cost.x.attrs["units"] == "km" and data.cost.x.values[1] - data.cost.x.values[0] == 25


@pytest.mark.needs_data(*NSIDC)
def test_nsidc_route_round_yamal_in_latlon(shared_data, tmp_path, capsys):
    """Baydaratskaya Bay -> the Gulf of Ob: round the Yamal peninsula (its northern tip, Bely
    Island, is at 73.3 N), never across it; ends and outputs in lat/lon."""
    out = tmp_path / "r.geojson"
    code = main(
        [
            "route",
            str(shared_data.joinpath(*NSIDC)),
            "--vessel",
            "Arc7",
            "--from",
            "70.3,66.0",
            "--to",
            "72.9,74.0",
            "--escort",  # every ice pixel is assumed thick first-year ice, 1.6 m: more than Arc7's 1.4 m
            "--out",
            str(out),
            "-q",
        ]
    )
    assert code == 0
    import json

    coords = np.array(json.loads(out.read_text())["geometry"]["coordinates"])
    lon, lat = coords[:, 0], coords[:, 1]
    assert lat[0] == pytest.approx(70.32, abs=0.01) and lon[0] == pytest.approx(65.75, abs=0.01)
    assert lat.max() > 73.3  # north of Bely Island
    assert lat[-1] == pytest.approx(72.82, abs=0.01)
    err = capsys.readouterr().err
    assert "thick first-year ice (WMO stage 93), an assumption" in err  # said even with -q


@pytest.mark.needs_data(*ROMS)
def test_roms_mask_is_read_with_its_options_and_the_projection_found(shared_data):
    path = str(shared_data.joinpath(*ROMS))
    data = open_chart(path, vessel="Arc7")
    mask = xr.open_dataset(path)["mask"].values
    np.testing.assert_array_equal(data.land.values, mask == 0)
    assert "land = mask == 0 (its option_0 is land)" in data.notes
    assert data.projection.source == "polar_stereographic.proj4_string"
    y, x = data.cost.y.values, data.cost.x.values
    assert x[1] - x[0] == pytest.approx(20.0)  # ROMS's X is in km already
    ll = data.projection.to_latlon([y[0]], [x[0]])[0]
    ds = xr.open_dataset(path)
    # The file's own 2-D latitude/longitude and its projection disagree by up to 17.8 km (its X/Y
    # sit about half a cell from the centres its latitude/longitude give): said, and within a pixel.
    assert ll == pytest.approx([float(ds.latitude[0, 0]), float(ds.longitude[0, 0])], abs=0.3)
    assert "aice: the file's latitude/longitude lie up to 17.8 km (0.89 pixel)" in " ".join(data.notes)
