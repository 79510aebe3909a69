"""`seaway route` and `seaway bench`, run as subprocesses: outputs, exit codes, messages; bad chart
files, Ctrl-C (exit status 130, no half-written output) and the search's progress on stderr."""

import json
import signal
import subprocess
import sys
import threading
import xml.etree.ElementTree as ET

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway import export
from seaway.base.interrupt import interruptible
from seaway.cli import main
from seaway.samples import ice_impact
from support.data import SHARED_DATA
from support.netcdf import small_dataset as _dataset
from support.netcdf import truncated_netcdf as _truncated

pytestmark = pytest.mark.cli


def run(*args, timeout=120):
    return subprocess.run(
        [sys.executable, "-m", "seaway", *args], capture_output=True, text=True, timeout=timeout
    )


@pytest.fixture(scope="module")
def chart_nc(tmp_path_factory):
    """A 60 x 80 stage-of-development chart at 70-76 N, 60-76 E: an island, thick first-year ice
    (stage 93) in the south, open water (55) elsewhere."""
    lat, lon = np.linspace(76.0, 70.0, 61), np.linspace(60.0, 76.0, 81)
    stage = np.full((61, 81), 55.0)
    stage[40:, :] = 93.0
    land = np.zeros((61, 81), bool)
    land[10:35, 30:45] = True
    stage[land] = np.nan
    conc = np.where(stage == 93.0, 10.0, 0.0)
    ds = xr.Dataset(
        {
            "stage_of_development": (("lat", "lon"), stage),
            "land": (("lat", "lon"), land),
            "sea_ice_concentration": (("lat", "lon"), conc),
        },
        coords={"lat": lat, "lon": lon},
    )
    path = tmp_path_factory.mktemp("chart") / "chart.nc"
    ds.to_netcdf(path)
    return path, ds


@pytest.mark.slow
def test_route_netcdf_all_outputs(chart_nc, tmp_path):
    path, ds = chart_nc
    outs = [tmp_path / f"r.{ext}" for ext in ("geojson", "gpx", "rtz", "csv", "html")]
    args = [
        "route",
        str(path),
        "--from",
        "73,61",
        "--to",
        "73,75",
        "--vessel",
        "Arc7",
        "--neighbourhood",
        "7",
        "--speed",
        "12",
        "--plot",
        str(tmp_path / "r.png"),
    ]
    for o in outs:
        args += ["--out", str(o)]
    done = run(*args)
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert lines[0].startswith("seaway route: 73-00.00N 061-00.00E -> 73-00.00N 075-00.00E")
    assert "reading" in done.stderr and "smoothed: cost" in done.stderr
    # the same route through the API, smoothed, costs what the files say
    u = ice_impact(ds.stage_of_development, "Arc7")
    r = seaway.route(u, (73, 61), (73, 75), land=ds.land, neighbourhood=7).smoothed()
    feature = json.loads(outs[0].read_text())
    assert feature["properties"]["cost"] == pytest.approx(r.cost, rel=1e-9)
    assert feature["properties"]["time_h"] == pytest.approx(r.length / 1.852 / 12, rel=1e-9)
    wps = (
        ET.parse(outs[2])
        .getroot()
        .findall("{http://www.cirm.org/RTZ/1/0}waypoints/{http://www.cirm.org/RTZ/1/0}waypoint")
    )
    assert len(wps) == len(r.waypoints) >= 3  # around the island
    gpx = ET.parse(outs[1]).getroot()
    assert len(gpx.findall(".//{http://www.topografix.com/GPX/1/1}rtept")) == len(wps)
    rows = outs[3].read_text().splitlines()
    head, rows = [x for x in rows if x.startswith("#")], [x for x in rows if not x.startswith("#")]
    assert head[1].startswith("# speed in ice: Andreeva 2021: V = F x V0, V0 12 kn")  # not open water's
    assert head[2:4] == [
        "# start 73.00000,61.00000 (requested 73,61)",
        "# end 73.00000,75.00000 (requested 73,75)",
    ]  # the ends used and asked for
    assert rows[0].startswith("waypoint,lat,lon,leg,course_deg") and len(rows) == len(wps) + 1
    assert "sea_ice_concentration_max" in rows[0]
    assert (tmp_path / "r.png").stat().st_size > 10_000
    page = outs[4].read_text()  # the interactive map: the same route, one popup per waypoint
    assert page.count('.bindPopup("') == len(wps) and "L.polyline(" in page
    assert "ice: WMO colour code by stage of development" in page  # a stage chart: by stage
    assert "ice free" in page and "thick first-year ice" in page  # the legend: open water too
    # the route never enters the island's closed squares: every waypoint is water
    assert np.all(~ds.land.values[tuple(np.rint(r.points).astype(int).T)])


def test_route_cost_variable_and_no_smooth(chart_nc, tmp_path):
    path, _ = chart_nc
    done = run(
        "route",
        str(path),
        "--variable",
        "sea_ice_concentration",
        "--from",
        "73,61",
        "--to",
        "74,75",
        "--no-smooth",
        "--edge-cost",
        "mean",
        "-q",
    )
    # -q leaves only what was assumed: the chart's 11 km land, which a route may cut
    assert done.returncode == 0 and done.stderr.startswith(
        "seaway route: land: the chart's own, on 11 km pixels"
    )
    assert "edge cost 'mean', 5x5 stencil" in done.stdout


@pytest.mark.parametrize(
    "args, code, message",
    [
        (["--from", "73,61", "--to", "72,50"], 1, "end (lat 72, lon 50) lies outside the chart"),
        (
            ["--from", "73,61", "--to", "74,67"],
            1,
            "end 74,67 is on an impassable pixel (land); the "
            "nearest point the ship may use is 74.0000,65.8000, 36.8 km away",
        ),  # 1.2 deg lon at 74 N
        # thick first-year ice south of 72 N: Arc5 may not enter (paper 000, Table 3); open water
        # begins at 72.1 N, 1.1 deg of latitude = 122.3 km north (R = 6371.0088 km)
        (
            ["--from", "71,61", "--to", "73,75", "--vessel", "Arc5"],
            1,
            "start 71,61 is on an impassable pixel (ice an Arc5 ship may not enter: thick first-year "
            "ice (WMO stage 93), total concentration 10/10); the nearest point the ship may use is "
            "72.1000,61.0000, 122.3 km away",
        ),
        (["--from", "73,61", "--to", "73,75", "--variable", "nope"], 1, "has no variable 'nope'"),
        (["--from", "73,61", "--to", "73,75", "--vessel", "Arc99"], 1, "ice_class must be one of"),
        (["--from", "73;61", "--to", "73,75"], 2, "expected LAT,LON"),
        (["--from", "73,61"], 2, "the following arguments are required: --to"),
        (["--from", "73,61", "--to", "73,75", "--neighbourhood", "4"], 2, "must be an odd integer"),
    ],
)
def test_route_errors(chart_nc, args, code, message):
    path, _ = chart_nc
    done = run("route", str(path), *args, "-q")
    assert done.returncode == code, done.stderr
    assert message in done.stderr and done.stdout == ""


def test_route_snap_and_missing_file(chart_nc, tmp_path):
    path, _ = chart_nc
    done = run("route", str(path), "--from", "73,61", "--to", "74,67", "--snap")
    assert done.returncode == 1  # 36.8 km is farther than --snap-km's 20 km
    assert (
        "the nearest point the ship may use is 74.0000,65.8000, 36.8 km away, farther than "
        "--snap-km 20: give a point in water the ship may use, or --snap-km 37"
    ) in done.stderr
    done = run("route", str(path), "--from", "73,61", "--to", "74,67", "--snap", "--snap-km", "40")
    assert done.returncode == 0, done.stderr
    assert "end 74,67 is on an impassable pixel (land): moved 36.8 km to 74.0000,65.8000" in done.stderr
    done = run("route", str(tmp_path / "none.nc"), "--from", "73,61", "--to", "74,67")
    assert done.returncode == 1 and "none.nc: no such file" in done.stderr


def test_broken_sigrid_file_is_a_clear_error(tmp_path):
    shp = tmp_path / "chart.shp"
    shp.write_bytes(b"")
    done = run("route", str(shp), "--from", "73,61", "--to", "74,67")
    assert done.returncode == 1
    assert "chart.shp" in done.stderr


DMI = SHARED_DATA / "ice_charts_sigrid3" / "dmi_greenland" / "201304100920_CapeFarewell_RIC.shp"


@pytest.mark.needs_data(DMI)
def test_route_on_a_real_sigrid3_chart(tmp_path):
    pytest.importorskip("pyogrio")
    out = tmp_path / "r.geojson"
    done = run(
        "route",
        str(DMI),
        "--from",
        "59.5,-44",
        "--to",
        "60.5,-48",
        "--vessel",
        "Arc7",
        "--grid",
        "59,61,-49,-43,0.01",
        "--no-smooth",
        "--out",
        str(out),
    )
    assert done.returncode == 0, done.stderr
    assert "200 x 600 pixels" in done.stderr  # the --grid: 2 x 6 degrees at 0.01
    feature = json.loads(out.read_text())
    # Open water south of Cape Farewell on 10 April 2013: paper 000 gives Arc7 u = 2 per km.
    assert feature["properties"]["cost"] == pytest.approx(2 * feature["properties"]["length"], rel=1e-9)
    bad = run("route", str(DMI), "--from", "59.5,-44", "--to", "60.5,-48", "--grid", "61,59,-49,-43,0.01")
    assert bad.returncode == 2 and "SOUTH < NORTH" in bad.stderr


def test_help_explains_every_option():
    done = run("route", "--help")
    assert done.returncode == 0
    for option in (
        "--from",
        "--to",
        "--vessel",
        "--variable",
        "--land-variable",
        "--neighbourhood",
        "--edge-cost",
        "--method",
        "--no-smooth",
        "--snap",
        "--speed",
        "--name",
        "--out",
        "--plot",
        "--quiet",
        "--depth",
        "--draft",
        "--ukc",
        "--depth-variable",
        "--depth-positive",
        "exit status: 0",
    ):
        assert option in done.stdout
    assert run("--help").returncode == 0 and run("bench", "--help").returncode == 0


def test_bench_small():
    done = run("bench", "--size", "95x115", "--neighbourhood", "3", "5", "--method", "astar", "--repeat", "1")
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert "synthetic_sea 95 x 115 pixels" in lines[0]
    cells = [line.split() for line in lines[2:]]
    assert [(c[0], int(c[1])) for c in cells] == [("astar", 3), ("astar", 5)]
    cost = seaway.samples.synthetic_sea((95, 115))
    s, e = seaway.samples.synthetic_endpoints((95, 115))
    exact = seaway.route(cost, s, e, neighbourhood=5, edge_cost="mean").cost
    assert float(cells[1][-1]) == pytest.approx(exact, abs=0.006)


# --- progress of a long search on stderr (issue 13) ----------------------------------------


@pytest.mark.skipif(
    threading.current_thread() is not threading.main_thread(), reason="the waiting main thread reports"
)
def test_the_cli_reports_pixels_settled_during_a_long_search(monkeypatch, capsys):
    """`seaway route`'s search block prints the token's count on stderr: a search that holds on
    until a line has been printed for its 28672 settled pixels (no clock in the test)."""
    from seaway.cli.common import Progress, searching

    monkeypatch.setattr(seaway.base.interrupt, "POLL_S", 0.001)
    monkeypatch.setattr(seaway.base.interrupt, "PROGRESS_EVERY_S", 0.0)
    chart = seaway.prepare(np.ones((200, 150)), neighbourhood=3)
    printed = threading.Event()

    class Told(Progress):
        def __call__(self, message):
            super().__call__(message)
            if "28,672 pixels" in message:  # earlier lines (while it runs) may come first
                printed.set()

    def search(token):
        chart.router.field(chart.model.engine(chart), 0, token)
        printed.wait()
        return "done"

    with searching(Told("route", quiet=False), 200 * 150):
        assert interruptible(search) == "done"
    err = capsys.readouterr().err
    assert "seaway route: [" in err and "searching: 28,672 pixels settled (96 % of the chart)" in err
    say_quiet = Progress("route", quiet=True)
    with searching(say_quiet, 200 * 150):
        chart.cost_field((0, 0))
    assert capsys.readouterr().err == ""


# --- bad chart files and interrupts: exit statuses, no half-written output -----------------


@pytest.mark.parametrize("cut", ["classic", "hdf5", "garbage"])
def test_cli_reports_a_bad_chart_file_with_exit_status_1(tmp_path, cut, capsys):
    if cut == "garbage":
        bad = tmp_path / "chart.nc"
        bad.write_bytes(b"\x00garbage" * 50)
    else:
        bad, _ = _truncated(tmp_path, "NETCDF3_64BIT" if cut == "classic" else "NETCDF4", 0.5)
    out = tmp_path / "route.geojson"
    code = main(
        ["route", str(bad), "--variable", "cost", "--from", "71,61", "--to", "73,69", "--out", str(out), "-q"]
    )
    err = capsys.readouterr().err
    assert code == 1
    assert f"seaway route: error: {bad}" in err
    assert ("truncated" in err) if cut == "classic" else ("cannot read it as NetCDF" in err)
    assert not out.exists()


def test_cli_interrupted_while_writing_exits_130_without_output(tmp_path, monkeypatch, capsys):
    path = tmp_path / "chart.nc"
    _dataset().to_netcdf(path)

    def interrupted(*a, **k):
        raise KeyboardInterrupt

    monkeypatch.setattr(export.os, "replace", interrupted)  # Ctrl-C just before the rename
    out = tmp_path / "route.geojson"
    code = main(
        ["route", str(path), "--variable", "cost", "--from", "71,61", "--to", "73,69", "--out", str(out)]
    )
    assert code == 130
    assert "seaway route: interrupted" in capsys.readouterr().err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["chart.nc"]


@pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")
def test_ctrl_c_in_the_cli_exits_130_and_writes_nothing(tmp_path):
    """A real SIGINT while `seaway route kara` loads the chart and routes."""
    out = tmp_path / "route.geojson"
    proc = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "seaway",
            "route",
            "kara",
            "--from",
            "70.3,58.5",
            "--to",
            "77.7005,103.987",  # water: the run would route and write, not stop at the end check
            "--out",
            str(out),
        ],
        stderr=subprocess.PIPE,
        stdout=subprocess.PIPE,
        text=True,
    )
    first = proc.stderr.readline()  # the first progress line: main() is running
    assert "reading kara" in first
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == 130, err
    assert "seaway route: interrupted" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == []


@pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")
def test_an_interrupt_that_passed_through_PyRun_String_still_exits_130(tmp_path):
    """The race behind a once-flaky run of the test above, made deterministic: the SIGINT lands
    while CPython runs code through PyRun_String (as Cython modules do on import), the
    KeyboardInterrupt is caught by the CLI, yet `python -m` would end the process by SIGINT
    (status -2). The entry point must exit 130 whatever the timing."""
    (tmp_path / "interrupted_in_pyrun.py").write_text(
        "import ctypes\n"
        "import seaway.cli as cli\n"
        "run = ctypes.pythonapi.PyRun_String\n"
        "run.argtypes = [ctypes.c_char_p, ctypes.c_int, ctypes.py_object, ctypes.py_object]\n"
        "run.restype = ctypes.py_object\n"
        "def route(args):\n"
        "    run(b'raise KeyboardInterrupt', 257, {}, {})  # 257: Py_file_input\n"
        "cli.run_route = route\n"
        "cli.entry(['route', 'kara', '--from', '70.3,58.5', '--to', '77.7,104'])\n"
    )
    proc = subprocess.run(
        [sys.executable, "-m", "interrupted_in_pyrun"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert proc.returncode == 130, proc.stderr
    assert proc.stderr.strip().endswith("seaway route: interrupted")
