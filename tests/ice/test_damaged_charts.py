"""Damaged vector charts (issue 27): a shapefile cut short, with flipped bits, a .dbf cut short,
an index from another chart, a GeoPackage cut short. Each is refused with one line naming the
file, what was lost and the fix; none reads as a partial chart (a .shp truncated to 90 % used to
lose 2 of its 23 polygons silently and route, exit 0) or ends in a GEOS traceback. Copies of a
real DMI chart are broken in tmp dirs at fixed seeds."""

import os
import shutil

import numpy as np
import pytest

import seaway
from seaway.cli import main
from seaway.ice.grids import latlon_grid
from seaway.ice.sigrid import read_sigrid3
from seaway.ice.vectorfile import check_shapefile_records

pytest.importorskip("pyogrio")
pytestmark = pytest.mark.needs_data("ice_charts_sigrid3", "dmi_greenland")

DMI = ("ice_charts_sigrid3", "dmi_greenland")
STEM = "201304100920_CapeFarewell_RIC"  # 23 polygons, 381 816 bytes of .shp
OTHER = "201307222045_CapeFarewell_RIC"  # 10 polygons
ROUTE = ["--from", "59.5,-44", "--to", "60.5,-48", "--vessel", "Arc7", "--grid", "59,61,-49,-43,0.05", "-q"]
FIX = "fetch the chart again (the download or copy did not finish, or the file is damaged)"


@pytest.fixture
def chart(shared_data, tmp_path):
    for ext in (".shp", ".dbf", ".shx", ".prj"):
        shutil.copy(shared_data.joinpath(*DMI, STEM + ext), tmp_path / (STEM + ext))
        os.chmod(tmp_path / (STEM + ext), 0o644)
    return tmp_path / (STEM + ".shp")


def _truncate(path, share):
    os.truncate(path, int(os.path.getsize(path) * share))


def _flip(path, flips, seed):
    data = bytearray(path.read_bytes())
    rng = np.random.default_rng(seed)
    for i in rng.integers(100, len(data), flips):  # past the header: the records
        data[i] ^= 1 << int(rng.integers(0, 8))
    path.write_bytes(bytes(data))


def _refused(chart, capsys):
    """The command line's exit status and its one line on stderr."""
    status = main(["route", str(chart), *ROUTE])
    err = capsys.readouterr().err.strip().splitlines()
    return status, err[-1]


def test_a_whole_chart_reads_every_record(chart):
    assert check_shapefile_records(str(chart)) == 23
    ds = read_sigrid3(chart, latlon_grid(59, 61, -49, -43, 0.05))
    assert ds.attrs["polygons"] == 23 and ds.attrs["features_without_geometry"] == 0


def test_a_shapefile_cut_to_90_percent_is_refused_naming_the_lost_features(chart, capsys):
    _truncate(chart, 0.9)
    status, line = _refused(chart, capsys)
    assert status == 1
    assert line == (
        f"seaway route: error: {chart} is cut short: it has 343634 of the 381816 bytes its header "
        f"declares, and 2 of its 23 features (records 22-23 of 23) lie in the missing part; {FIX}"
    )
    with pytest.raises(seaway.ChartError, match="2 of its 23 features"):
        seaway.open_chart(chart, grid=(59, 61, -49, -43, 0.05))


def test_flipped_bits_are_refused_naming_the_feature_not_a_geos_traceback(chart, capsys):
    _flip(chart, 50, seed=0)  # used to end in shapely.errors.GEOSException's traceback
    status, line = _refused(chart, capsys)
    assert status == 1
    assert line == (
        f"seaway route: error: {chart}: the geometry of feature 22 cannot be read (Points of "
        f"LinearRing do not form a closed linestring); {FIX}"
    )


def test_a_dbf_cut_short_is_refused_naming_the_records_without_attributes(chart):
    _truncate(chart.with_suffix(".dbf"), 0.9)
    with pytest.raises(
        ValueError, match=r"holds 19 of the 23 attribute records .* records 20-23 of 23 are lost"
    ):
        read_sigrid3(chart, latlon_grid(59, 61, -49, -43, 0.05))


def test_an_index_from_another_chart_is_refused(chart, shared_data):
    shutil.copy(shared_data.joinpath(*DMI, OTHER + ".shx"), chart.with_suffix(".shx"))
    with pytest.raises(
        ValueError, match=r"\.shx: its entry for record 1 of 10 does not point at that record"
    ):
        check_shapefile_records(str(chart))


def test_an_index_cut_short_or_not_an_index(chart):
    shx = chart.with_suffix(".shx")
    _truncate(shx, 0.9)
    with pytest.raises(ValueError, match=r"\.shx: the index declares 284 bytes but has 255"):
        check_shapefile_records(str(chart))
    shx.write_bytes(b"\x00" * 50)
    with pytest.raises(ValueError, match=r"\.shx is cut short: 50 bytes, less than a shapefile index"):
        check_shapefile_records(str(chart))
    shx.write_bytes(b"GIF89a" + b"\x00" * 200)
    with pytest.raises(ValueError, match=r"\.shx is not a shapefile index \(\.shx\): it starts 47494638"):
        check_shapefile_records(str(chart))


def test_features_without_geometry_are_said(chart, tmp_path):
    import pyogrio.raw

    meta, _, wkb, fields = pyogrio.raw.read(chart)
    wkb = wkb.copy()
    wkb[3] = None  # a null record: nothing is lost, but the chart has a hole there
    out = tmp_path / "null.shp"
    pyogrio.raw.write(out, wkb, fields, meta["fields"], crs=meta["crs"], geometry_type="Polygon")
    c = seaway.open_chart(out, grid=(59, 61, -49, -43, 0.05))
    assert f"{out}: 1 of its 23 features have no geometry (null records): they add no ice" in c.notes


@pytest.mark.needs_data("ice_charts_sigrid3", "cis_eastern_arctic")
def test_a_geopackage_cut_short_is_refused(shared_data, tmp_path):
    src = shared_data / "ice_charts_sigrid3" / "cis_eastern_arctic" / "cis_SGRDREA_20201102T.gpkg"
    gpkg = tmp_path / "cis.gpkg"
    gpkg.write_bytes(src.read_bytes()[: int(src.stat().st_size * 0.9)])
    with pytest.raises(
        ValueError, match=r"cis\.gpkg: cannot read it as a SIGRID-3 vector file \(.*malformed"
    ):
        read_sigrid3(gpkg, latlon_grid(60, 75, -80, -50, 0.25))
