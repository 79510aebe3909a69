"""Readers (seaway.ice.sigrid) on the real charts in ../shared/data: SIGRID-3 shapefiles (DMI)
and a GeoPackage (CIS), NSIDC G02202 NetCDF; values checked on known polygons."""

import sys

import numpy as np
import pytest

from seaway.ice import codes, polaris
from seaway.ice.grids import latlon_grid, projected_grid
from seaway.icenav import summary
from support.data import SHARED_DATA

DATA = SHARED_DATA
pytestmark = pytest.mark.needs_data
CIS = DATA / "ice_charts_sigrid3/cis_eastern_arctic/cis_SGRDREA_20201102T.gpkg"
DMI_SW = DATA / "ice_charts_sigrid3/dmi_greenland/201405011000_SouthWest_RIC.shp"
DMI_CF = DATA / "ice_charts_sigrid3/dmi_greenland/201304100920_CapeFarewell_RIC.shp"
NSIDC = DATA / "sea_ice_concentration/seaice_conc_daily_nh_20211231_f17_v04r00.nc"


def _features(path):
    """(attributes by field, shapely geometries, CRS) read with pyogrio, independently of the
    reader under test."""
    import pyogrio.raw
    import shapely
    import shapely.ops

    meta, _, wkb, data = pyogrio.raw.read(path)
    return dict(zip(meta["fields"], data)), shapely.from_wkb(wkb), meta["crs"]


def _inside_pixel(geom, crs, grid, ds):
    """The pixel of `grid` holding a point deep inside `geom` (pole of inaccessibility)."""
    import pyproj
    import shapely
    import shapely.ops

    tr = pyproj.Transformer.from_crs(crs, grid.crs, always_xy=True)
    g = shapely.transform(geom, lambda xy: np.column_stack(tr.transform(xy[:, 0], xy[:, 1])))
    p = shapely.ops.polylabel(g, tolerance=g.length / 1000)
    x, y = p.x / grid.scale, p.y / grid.scale
    r, c = int(np.abs(grid.y - y).argmin()), int(np.abs(grid.x - x).argmin())
    return ds.isel({grid.dims()[0]: r, grid.dims()[1]: c})


def _first(fields, **want):
    n = len(next(iter(fields.values())))
    return next(i for i in range(n) if all(fields[k][i] == v for k, v in want.items()))


@pytest.fixture(scope="module")
def cis_polar():
    from seaway.ice.sigrid import read_sigrid3

    grid = projected_grid("EPSG:3413", -2100, 500, -3000, -300, 5)  # NSIDC polar stereographic
    return grid, read_sigrid3(CIS, grid)


def test_cis_geopackage_on_polar_stereographic_grid(cis_polar):
    grid, ds = cis_polar
    fields, geoms, crs = _features(CIS)
    assert ds.attrs["polygons"] == 432 and ds.attrs["repaired_polygons"] == 0
    # An ice polygon with two partial concentrations: CT 80 CA 40 SA 84 CB 40 SB 81.
    i = _first(fields, CT="80", CA="40", SA="84", CB="40", SB="81")
    px = _inside_pixel(geoms[i], crs, grid, ds)
    assert int(px.polygon) == i
    got = {k: float(px[k]) for k in ("CT", "CA", "SA", "CB", "SB")}
    assert got == {"CT": 8.0, "CA": 4.0, "SA": 84.0, "CB": 4.0, "SB": 81.0}
    assert np.isnan(px.SC) and not bool(px.land) and not bool(px.off_chart)
    # Land (NULL attributes), ice shelf, and the water polygon (CT '00').
    for ptype, land, shelf in (("L", True, False), ("S", True, True)):
        j = max((k for k in range(432) if fields["POLY_TYPE"][k] == ptype), key=lambda k: geoms[k].area)
        px = _inside_pixel(geoms[j], crs, grid, ds)
        assert (int(px.polygon), bool(px.land), bool(px.ice_shelf)) == (j, land, shelf)
        assert np.isnan(px.CT) and np.isnan(px.SA)
    w = _first(fields, POLY_TYPE="W")
    px = _inside_pixel(geoms[w], crs, grid, ds)
    assert float(px.CT) == 0 and np.isnan(px.SA) and not bool(px.land)
    # Multi-year ice (97) and a 9-10/10 code (91 -> 10 tenths, the upper end).
    m = _first(fields, SA="97")
    assert int(_inside_pixel(geoms[m], crs, grid, ds).SA) == 97
    assert grid.dims() == ("y", "x") and ds.x.attrs["units"] == "km"
    assert np.nanmax(ds.CT.values) == 10 and set(np.unique(ds.SA.values[~np.isnan(ds.SA.values)])) <= set(
        codes.STAGE_CODES
    )


def test_dmi_shapefiles_single_digit_codes_ranges_and_missing_partials():
    from seaway.ice.sigrid import read_sigrid3

    grid = latlon_grid(65.0, 71.0, -64.0, -50.0, (0.02, 0.05))
    ds = read_sigrid3(DMI_SW, grid)
    fields, geoms, crs = _features(DMI_SW)
    cases = [  # attributes as written in the file -> decoded values at a pixel inside
        ({"CT": "1", "SA": "98", "SB": "88"}, {"CT": 1.0, "CA": 1.0, "SA": 98.0, "CB": 0.0, "SB": 88.0}),
        ({"CT": "91", "SA": "91"}, {"CT": 10.0, "CA": 10.0, "SA": 91.0, "CB": np.nan, "SB": np.nan}),
        (
            {"CT": "46", "SA": "87", "SB": "-9"},
            {"CT": 6.0, "CA": 6.0, "SA": 87.0, "CB": np.nan, "SB": np.nan},
        ),
        ({"CT": "13", "SA": "88", "SB": "85"}, {"CT": 3.0, "CA": 3.0, "SA": 88.0, "CB": 0.0, "SB": 85.0}),
    ]
    for attrs, expected in cases:
        i = max(
            (k for k in range(len(geoms)) if all(fields[f][k] == v for f, v in attrs.items())),
            key=lambda k: geoms[k].area,
        )
        px = _inside_pixel(geoms[i], crs, grid, ds)
        assert int(px.polygon) == i
        got = {k: float(px[k]) for k in expected}
        np.testing.assert_equal(got, expected)
    mean = read_sigrid3(DMI_SW, grid, concentration="mean")
    i = _first(fields, CT="46")
    assert float(_inside_pixel(geoms[i], crs, grid, mean).CT) == 5.0
    # The 2013 Cape Farewell chart: old ice (95) and thin FY (87), CT '12', no partials.
    cf = read_sigrid3(DMI_CF, latlon_grid(56, 64, -56, -37, (0.05, 0.1)))
    f2, g2, crs2 = _features(DMI_CF)
    i = max((k for k in range(len(g2)) if f2["CT"][k] == "12"), key=lambda k: g2[k].area)
    px = _inside_pixel(g2[i], crs2, latlon_grid(56, 64, -56, -37, (0.05, 0.1)), cf)
    assert {k: float(px[k]) for k in ("CT", "CA", "SA", "CB", "SB")} == {
        "CT": 2.0,
        "CA": 2.0,
        "SA": 95.0,
        "CB": 0.0,
        "SB": 87.0,
    }
    # POLARIS there: 8/10 open water (3) + 2/10 old ice (-> heavy MY: PC5 -2) = 20.
    assert float(polaris.polaris_chart(cf, "PC5").rio.sel(lat=px.lat, lon=px.lon)) == 20


def test_invalid_rings_and_text_codes_are_repaired(tmp_path):
    import pyogrio.raw
    import shapely
    import shapely.ops

    from seaway.ice.sigrid import read_sigrid3

    bowtie = shapely.Polygon([(0, 0), (2, 2), (2, 0), (0, 2), (0, 0)])  # self-intersecting
    square = shapely.box(3, 0, 5, 2)
    assert not bowtie.is_valid
    path = tmp_path / "chart.gpkg"
    fields = ["CT", "CA", "SA", "POLY_TYPE"]
    data = [
        np.array(v, dtype=object)
        for v in (["57", " X ", None], ["-9", "-9", None], ["3", "86", None], ["I", "I", "L"])
    ]
    land = shapely.box(6, 0, 7, 2)
    pyogrio.raw.write(
        path,
        shapely.to_wkb(np.array([bowtie, square, land])),
        data,
        fields,
        crs="EPSG:4326",
        geometry_type="Polygon",
        driver="GPKG",
    )
    ds = read_sigrid3(path, latlon_grid(0, 2, 0, 8, 0.1))
    assert ds.attrs["repaired_polygons"] == 1
    at = lambda lat, lon: ds.sel(lat=lat, lon=lon, method="nearest")  # noqa: E731
    for lon in (0.5, 1.5):  # both triangles of the bow tie
        assert (float(at(1.0, lon).CT), float(at(1.0, lon).SA)) == (7.0, 99.0)  # '3' -> unknown
    assert np.isnan(at(1.0, 4.0).CT) and float(at(1.0, 4.0).SA) == 86  # 'X' -> unknown CT
    assert bool(at(1.0, 6.5).land) and bool(at(1.0, 7.5).off_chart)


def test_nsidc_g02202_native_and_on_a_latlon_grid():
    from seaway.ice.sigrid import read_nsidc_g02202

    native = read_nsidc_g02202(NSIDC)
    assert native.CT.shape == (448, 304) and native.attrs["crs"].startswith("+proj=stere")
    assert native.x.values[0] == -3837.5 and native.y.values[0] == 5837.5  # km
    assert float(np.nanmax(native.CT)) == 10 and 0.4 < float(native.land.mean()) < 0.6
    grid = latlon_grid(70.0, 80.0, 20.0, 130.0, 0.5)
    ds = read_nsidc_g02202(NSIDC, grid, stage=93)
    at = lambda lat, lon: ds.sel(lat=lat, lon=lon, method="nearest")  # noqa: E731
    assert float(at(75, 70).CT) == 10 and float(at(76, 125).CT) == 10  # Kara, Laptev (README)
    assert float(at(74, 30).CT) == 0 and np.isnan(at(74, 30).SA)  # Barents: open
    assert float(at(75, 70).SA) == 93  # the stage we chose to assume
    assert bool(at(72.25, 105.25).land)  # Taymyr
    # Land = flags 252 lakes + 253 coast + 254 land (665 + 4561 + 63707 cells in this file,
    # which has no pole-hole (251) or missing (255) cells: the CDR fills the pole hole).
    assert int(native.land.sum()) == 665 + 4561 + 63707
    pole = read_nsidc_g02202(NSIDC, latlon_grid(89.5, 90.0, 0, 10, 0.25))
    assert (pole.CT.values == 10).all() and not pole.off_chart.values.any()
    south = read_nsidc_g02202(NSIDC, latlon_grid(-60, -50, 0, 10, 5.0))
    assert south.off_chart.values.all() and np.isnan(south.CT.values).all()  # unknown there


def test_nsidc_monthly_file_names_its_variable():
    """The monthly file's concentration is cdr_seaice_conc_monthly: without variable= the
    reader names the variables it found and the argument to pass (issue 30)."""
    from seaway import ChartError
    from seaway.ice.sigrid import read_nsidc_g02202

    monthly = SHARED_DATA / "sea_ice_concentration" / "seaice_conc_monthly_nh_202112_f17_v04r00.nc"
    with pytest.raises(ChartError) as err:
        read_nsidc_g02202(monthly)
    said = str(err.value)
    assert "has no variable 'cdr_seaice_conc'" in said
    assert "cdr_seaice_conc_monthly, melt_onset_day_cdr_seaice_conc_monthly" in said
    assert (
        'pass variable="cdr_seaice_conc_monthly" (seaway route: --variable cdr_seaice_conc_monthly)' in said
    )
    ds = read_nsidc_g02202(monthly, variable="cdr_seaice_conc_monthly")
    assert ds.CT.shape == (448, 304) and float(np.nanmax(ds.CT)) == 10
    assert int(ds.land.sum()) == 665 + 4561 + 63707  # the daily file's flags (test above)


def test_real_chart_route_and_summary():
    import seaway
    from seaway.ice.sigrid import read_sigrid3

    grid = latlon_grid(62, 84, -113, -22, (0.1, 0.25))
    ds = read_sigrid3(CIS, grid)
    pc = polaris.polaris_chart(ds, "PC7", v0_kn=12)
    r = seaway.route(pc.cost, (64, -57), (75, -70), land=ds.land)  # Davis Strait -> Baffin Bay
    s = summary.summarize(r, ds, time_cost=pc.cost, polaris=pc)
    assert s["time"] == pytest.approx(r.cost) and s["length"] == pytest.approx(r.length)
    assert s["length"] == pytest.approx(r.cost * 12 * 1.852)  # normal operation all the way
    assert 1200 < s["length"] < 1450
    assert set(s["by_stage"]) == {"bergy water", "new ice"}  # CT 02 SA 98 FA 10, then new ice 5/10
    assert sum(v["distance"] for v in s["by_stage"].values()) == pytest.approx(s["length"])
    assert s["rio_min"] == 9 * 3 + 1 * -3 and not s["elevated_risk"]  # 1/10 glacier ice: HMY -3


def test_missing_extra_gives_the_install_hint(monkeypatch):
    from seaway.ice import sigrid

    monkeypatch.setitem(sys.modules, "pyogrio.raw", None)
    with pytest.raises(ImportError, match=r'pip install "seaway\[ice\]"'):
        sigrid.read_sigrid3(CIS, latlon_grid(0, 1, 0, 1, 0.5))
