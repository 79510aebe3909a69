"""Errors: one base (issue 28 item 4). Bad input to any layer of the public API raises a
seaway.SeawayError of the kind that fits (ChartError, ForecastError, VesselFileError,
SeawayTypeError for a wrong type, SeawayError for the rest) whose message names the fix, and
no library file raises a bare ValueError or TypeError on bad input."""

import pathlib
import re

import numpy as np
import pytest

import seaway
import seaway.constraints
import seaway.depth
import seaway.ice
import seaway.samples
from seaway import ChartError, ForecastError, SeawayError, SeawayTypeError, VesselFileError

C = np.ones((4, 5))
SRC = pathlib.Path(seaway.__file__).parent
#: raise ValueError/TypeError left in src/seaway: internal control flow, caught a few lines on
#: and never seen by a caller (a damaged NetCDF header; a malformed voyage row of route_many).
ALLOWED = {
    ("base/readers.py", 'raise ValueError("bad attribute list")'),
    ("base/readers.py", 'raise ValueError("bad variable list")'),
    ("fleet/one.py", "raise ValueError"),
}


def _negative():
    c = C.copy()
    c[1, 1] = -1
    return c


def _file(tmp_path, name, data):
    path = tmp_path / name
    path.write_bytes(data)
    return path


def _vessel(tmp_path, text):
    from seaway.vessel import load

    return load(_file(tmp_path, "ship.toml", text.encode()))


# (label, call(tmp_path), expected class, the message names the cause and the fix)
CASES = [
    # arrays and arguments of seaway.route (the chart and engine layers)
    ("negative cost", lambda t: seaway.route(_negative(), (0, 0), (0, 4)), ChartError, r"costs must be >= 0"),
    ("3-D cost", lambda t: seaway.route(np.ones((2, 4, 5)), (0, 0), (0, 4)), ChartError, r"give one \(rows"),
    (
        "empty cost",
        lambda t: seaway.route(np.ones((0, 5)), (0, 0), (0, 4)),
        ChartError,
        r"at least one pixel",
    ),
    ("complex cost", lambda t: seaway.route(C + 1j, (0, 0), (0, 4)), SeawayTypeError, r"real numbers"),
    (
        "land not 0/1",
        lambda t: seaway.route(C, (0, 0), (0, 4), land=np.full(C.shape, 2)),
        ChartError,
        r"land must hold only 0 \(sea\) and 1 \(land\).*give a bool mask",
    ),
    (
        "land of another shape",
        lambda t: seaway.route(C, (0, 0), (0, 4), land=np.zeros((3, 3), bool)),
        ChartError,
        r"give a mask of the same shape",
    ),
    (
        "lat/lon not matching",
        lambda t: seaway.route(C, (50, 0), (51, 1), lat=np.arange(3.0), lon=np.arange(5.0)),
        ChartError,
        r"one latitude per row",
    ),
    (
        "end outside",
        lambda t: seaway.route(C, (0, 0), (9, 9)),
        SeawayError,
        r"lies outside the chart.*give a \(row, col\) pixel index",
    ),
    (
        "end not numbers",
        lambda t: seaway.route(C, "ab", (0, 4)),
        SeawayTypeError,
        r"must be a pair of numbers",
    ),
    (
        "even stencil",
        lambda t: seaway.route(C, (0, 0), (0, 4), neighbourhood=4),
        SeawayError,
        r"neighbourhood=5",
    ),
    (
        "stencil as text",
        lambda t: seaway.route(C, (0, 0), (0, 4), neighbourhood="5"),
        SeawayTypeError,
        r"odd",
    ),
    ("unknown method", lambda t: seaway.route(C, (0, 0), (0, 4), method="fast"), SeawayError, r"one of"),
    (
        "one via point",
        lambda t: seaway.route(C, (0, 0), (0, 4), via=(1, 2)),
        SeawayTypeError,
        r"write via=\[\(1, 2\)\]",
    ),
    (
        "empty turn table",
        lambda t: seaway.route(C, (0, 0), (0, 4), turn_penalty={}),
        SeawayError,
        r"give e\.g\.",
    ),
    # constraints
    ("negative keep-away", lambda t: seaway.constraints.KeepAway(km=-1), SeawayError, r"finite number >= 0"),
    ("zone factor below 1", lambda t: seaway.constraints.Zone({}, penalty=0.5), SeawayError, r"or inf"),
    # chart files
    ("missing chart", lambda t: seaway.open_chart(t / "none.nc"), ChartError, r"no such file"),
    ("empty chart", lambda t: seaway.open_chart(_file(t, "e.nc", b"")), ChartError, r"fetch it again"),
    ("garbage chart", lambda t: seaway.open_chart(_file(t, "g.nc", b"junk" * 9)), ChartError, r"not NetCDF"),
    (
        "garbage shapefile",
        lambda t: seaway.open_chart(_file(t, "g.shp", b"junk")),
        ChartError,
        r"copy g\.dbf",
    ),
    ("garbage season", lambda t: seaway.open_season(_file(t, "s.nc", b"junk" * 9)), ChartError, r"time axis"),
    ("missing bathymetry", lambda t: seaway.depth.open_bathymetry(t / "b.nc"), ChartError, r"no such"),
    # forecast files
    ("missing forecast", lambda t: seaway.open_forecast(t / "none.nc"), ForecastError, r"no such file"),
    (
        "garbage forecast",
        lambda t: seaway.open_forecast(_file(t, "f.nc", b"junk" * 9)),
        ForecastError,
        r"CF NetCDF",
    ),
    # vessel files
    (
        "vessel unknown field",
        lambda t: _vessel(t, 'name = "x"\ndraught_m = 9'),
        VesselFileError,
        r"draft_m\?",
    ),
    (
        "vessel bad speed",
        lambda t: _vessel(t, 'name = "x"\nservice_speed_kn = -3'),
        VesselFileError,
        r"positive",
    ),
    # ice: codes, classes and rules
    (
        "ice stage without an impact",
        lambda t: seaway.ice.ice_impact(np.array([[85.0, 7.0]]), "Arc7"),
        ChartError,
        r"Pass unknown=np\.inf",
    ),
    ("unknown ice class", lambda t: seaway.ice.get_class("Arc12"), SeawayError, r"ice_class must be one of"),
    ("unknown fast-ice rule", lambda t: seaway.ice.check_fast_ice("sometimes"), SeawayError, r"'nearby'"),
    # depth, samples, output
    ("draft as text", lambda t: seaway.depth.check_draft("deep"), SeawayTypeError, r"number of metres"),
    ("draft too deep", lambda t: seaway.depth.check_draft(500), SeawayError, r"less than 100"),
    ("sample of one axis", lambda t: seaway.samples.kara_sea(shape=(1,)), SeawayError, r"\(rows, cols\)"),
    (
        "unknown export format",
        lambda t: seaway.export.write(seaway.route(C, (0, 0), (0, 4)), t / "r.xyz"),
        SeawayError,
        r"use one of the extensions",
    ),
]


@pytest.mark.parametrize("label, call, kind, fix", CASES, ids=[c[0] for c in CASES])
def test_bad_input_raises_the_fitting_seaway_error(tmp_path, label, call, kind, fix):
    with pytest.raises(SeawayError, match=fix) as e:
        call(tmp_path)
    assert type(e.value) is kind, f"{label}: {type(e.value).__name__}, not {kind.__name__}: {e.value}"
    assert isinstance(e.value, ValueError)  # handlers written for ValueError still catch it


def test_the_kinds_are_one_family():
    for kind in (
        ChartError,
        ForecastError,
        VesselFileError,
        SeawayTypeError,
        seaway.SnapError,
        seaway.NoRouteError,
    ):
        assert issubclass(kind, SeawayError) and issubclass(kind, ValueError)
    assert issubclass(SeawayTypeError, TypeError)
    assert len({c[2] for c in CASES}) == 5 and len(CASES) >= 20


def test_no_bare_value_or_type_error_is_raised_in_the_library():
    """Every raise on bad input is a seaway error; the allow-list is internal control flow."""
    found = set()
    for path in SRC.rglob("*.py"):
        for line in path.read_text().splitlines():
            if re.match(r"\s*raise (ValueError|TypeError)\b", line):
                found.add((path.relative_to(SRC).as_posix(), line.strip()))
    assert found == ALLOWED
