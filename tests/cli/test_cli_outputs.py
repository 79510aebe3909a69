"""`seaway route --out/--plot`: every output path is checked before the chart is read or the
route searched, and the outputs are written all or nothing (no temporary file left or named)."""

import json
import os

import pytest

from seaway.base.files import write_all
from seaway.cli import main
from support.netcdf import small_dataset

pytestmark = pytest.mark.cli
DMI = ("ice_charts_sigrid3", "dmi_greenland", "201304100920_CapeFarewell_RIC.shp")
ENDS = ["--from", "71,61", "--to", "73,69"]


@pytest.fixture
def chart(tmp_path):
    path = tmp_path / "chart.nc"
    small_dataset().to_netcdf(path)
    return str(path)


@pytest.mark.parametrize(
    "name, option, message",
    [
        ("missing/r.gpx", "--out", "--out {p}: the directory {d} does not exist; create it first"),
        (
            "r.txt",
            "--out",
            "--out {p}: cannot tell the format from the extension '.txt'; use one of "
            ".csv, .geojson, .gpx, .htm, .html, .json, .rtz",
        ),
        ("r.jpg", "--plot", "--plot {p}: cannot tell the format from the extension '.jpg'; use one of .png"),
        ("adir", "--out", "--out {p} is a directory; give a file name inside it"),
    ],
)
def test_a_bad_output_path_stops_the_run_before_the_chart_is_read(
    chart, tmp_path, capsys, name, option, message
):
    (tmp_path / "adir").mkdir()
    bad = tmp_path / name
    code = main(
        ["route", chart, "--variable", "cost", *ENDS, "--out", str(tmp_path / "ok.geojson"), option, str(bad)]
    )
    err = capsys.readouterr().err
    assert code == 1
    assert message.format(p=bad, d=bad.parent) in err
    assert "reading" not in err and "routing" not in err  # nothing was done
    assert sorted(p.name for p in tmp_path.iterdir()) == ["adir", "chart.nc"]


def test_an_output_given_twice_is_refused(chart, tmp_path, capsys):
    out = tmp_path / "r.csv"
    assert (
        main(
            [
                "route",
                chart,
                "--variable",
                "cost",
                *ENDS,
                "--out",
                str(out),
                "--out",
                str(tmp_path / "." / "r.csv"),
            ]
        )
        == 1
    )
    assert f"{tmp_path / '.' / 'r.csv'} is given twice" in capsys.readouterr().err


def test_outputs_are_written_all_or_nothing(chart, tmp_path, monkeypatch, capsys):
    """The second file fails while it is written (disk full): neither file appears, no
    temporary file is left, and the message names the file, not a temporary one."""
    outs = [tmp_path / "r.geojson", tmp_path / "r.gpx"]
    real_fdopen, calls = os.fdopen, []

    def fdopen(fd, *a, **k):
        calls.append(fd)
        if len(calls) == 2:
            os.close(fd)
            raise OSError(28, "No space left on device")
        return real_fdopen(fd, *a, **k)

    monkeypatch.setattr(os, "fdopen", fdopen)
    code = main(
        ["route", chart, "--variable", "cost", *ENDS, "--out", str(outs[0]), "--out", str(outs[1]), "-q"]
    )
    err = capsys.readouterr().err
    assert code == 1
    assert f"error: [Errno 28] {outs[1]}: cannot write it (No space left on device)" in err
    assert ".seaway-" not in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["chart.nc"]
    monkeypatch.setattr(os, "fdopen", real_fdopen)
    assert (
        main(
            ["route", chart, "--variable", "cost", *ENDS, "--out", str(outs[0]), "--out", str(outs[1]), "-q"]
        )
        == 0
    )
    assert json.loads(outs[0].read_text())["properties"]["cost"] > 0 and outs[1].stat().st_size > 0


def test_write_all_names_the_target_never_the_temporary_file(tmp_path):
    ok, bad = tmp_path / "a.csv", tmp_path / "gone" / "b.csv"
    with pytest.raises(FileNotFoundError) as e:
        write_all([(ok, "a"), (bad, b"b")])
    assert str(e.value) == f"[Errno 2] {bad}: cannot write it (No such file or directory)"
    assert list(tmp_path.iterdir()) == []
    write_all([(ok, "a"), (tmp_path / "c.png", b"\x89PNG")])
    assert ok.read_text() == "a" and (tmp_path / "c.png").read_bytes() == b"\x89PNG"
    assert oct(ok.stat().st_mode & 0o777) == oct(0o666 & ~_umask())


def _umask():
    mask = os.umask(0)
    os.umask(mask)
    return mask


@pytest.mark.needs_data(*DMI)
def test_a_real_chart_run_checks_its_outputs_first(shared_data, tmp_path, capsys):
    """On the real DMI chart: a PNG into a missing folder stops the run before the chart is
    rasterised; the GeoJSON beside it is not written."""
    pytest.importorskip("pyogrio")
    out, png = tmp_path / "r.geojson", tmp_path / "maps" / "r.png"
    code = main(
        [
            "route",
            str(shared_data.joinpath(*DMI)),
            "--from",
            "59.5,-44",
            "--to",
            "60.5,-48",
            "--vessel",
            "Arc7",
            "--out",
            str(out),
            "--plot",
            str(png),
        ]
    )
    err = capsys.readouterr().err
    assert code == 1 and f"--plot {png}: the directory {png.parent} does not exist" in err
    assert "reading" not in err and not out.exists()
