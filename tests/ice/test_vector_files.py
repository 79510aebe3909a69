"""A vector chart that cannot be read as given is refused naming the missing or broken part; a
shapefile without .prj is read as WGS 84 and that assumption is said (real DMI charts)."""

import shutil

import pytest

from seaway.cli import main
from seaway.ice.vectorfile import check_vector_file

DMI = ("ice_charts_sigrid3", "dmi_greenland")
STEM = "201304100920_CapeFarewell_RIC"
ROUTE = ["--from", "59.5,-44", "--to", "60.5,-42", "-q", "--no-smooth"]


@pytest.fixture
def chart(shared_data, tmp_path):
    """A copy of a real DMI shapefile and its sidecars, to break."""
    for ext in (".shp", ".dbf", ".shx", ".prj"):
        shutil.copy(shared_data.joinpath(*DMI, STEM + ext), tmp_path / (STEM + ext))
    return tmp_path / (STEM + ".shp")


@pytest.mark.needs_data(*DMI)
def test_whole_shapefile_needs_no_assumption(chart):
    assert check_vector_file(chart) == []


@pytest.mark.needs_data(*DMI)
def test_missing_prj_is_read_as_wgs84_and_said(chart, capsys):
    with_prj = main(["route", str(chart), *ROUTE])
    first = capsys.readouterr()
    chart.with_suffix(".prj").unlink()
    assert main(["route", str(chart), *ROUTE]) == with_prj == 0
    second = capsys.readouterr()
    assert f"{STEM}.shp has no .prj: its coordinates are read as WGS 84" in second.err
    assert "no .prj" not in first.err
    # the DMI chart is in WGS 84: the same route; the route records the assumption
    assert [x for x in second.out.splitlines() if "no .prj" not in x] == first.out.splitlines()
    assert "assumed: " in second.out and "has no .prj" in second.out


@pytest.mark.needs_data(*DMI)
@pytest.mark.parametrize("text", ["GARBAGE", ""])
def test_unusable_prj_is_refused(chart, text):
    chart.with_suffix(".prj").write_text(text)
    with pytest.raises(ValueError, match=r"\.prj does not describe a CRS .* delete it to read"):
        check_vector_file(chart)


@pytest.mark.needs_data(*DMI)
@pytest.mark.parametrize("ext, what", [(".dbf", "attribute table"), (".shx", "index of shapes")])
def test_missing_sidecar_is_named(chart, ext, what, capsys):
    chart.with_suffix(ext).unlink()
    assert main(["route", str(chart), *ROUTE]) == 1
    err = capsys.readouterr().err
    assert f"the shapefile's {ext} (its {what}" in err and f"copy {STEM}{ext}" in err


def test_no_prj_with_projected_coordinates_is_refused(tmp_path):
    shp = tmp_path / "c.shp"
    for ext in (".shp", ".dbf", ".shx"):
        (tmp_path / f"c{ext}").write_bytes(b"x")
    with pytest.raises(ValueError, match=r"has no \.prj and its coordinates .* are not degrees"):
        check_vector_file(shp, bounds=(-2e6, -1e6, 2e6, 1e6))
    assert "an assumption" in check_vector_file(shp, bounds=(-50, 55, -40, 62))[0]


def test_empty_file_and_directory_are_named(tmp_path, capsys):
    (tmp_path / "empty.shp").write_bytes(b"")
    (tmp_path / "charts.shp").mkdir()
    (tmp_path / "charts.shp" / "a.shp").write_bytes(b"x")
    assert main(["route", str(tmp_path / "empty.shp"), *ROUTE]) == 1
    assert "empty.shp is empty (0 bytes)" in capsys.readouterr().err
    assert main(["route", str(tmp_path / "charts.shp"), *ROUTE]) == 1
    assert (
        "is a directory, not a chart file; give the chart file (.shp or .gpkg) inside it; "
        "it holds a.shp" in capsys.readouterr().err
    )
