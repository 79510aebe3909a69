"""The hostile-input campaign of issue 27 for files, kept in the suite (seeded, a few seconds):
small valid files are written (a NetCDF-4 and a classic NetCDF cost chart, a GeoTIFF, a SIGRID-3
shapefile and GeoPackage, a NetCDF season, a CF forecast, a vessel file) and broken at fixed
seeds: emptied, truncated, bits flipped, another format's magic, garbage, a shapefile's part
broken. seaway.open_chart, open_season, open_forecast, vessel.load and the command line's main()
must answer or refuse in one line from seaway's own code (support.hostile); a truncated binary
file that is still read must give the whole file's route (else it was read in part, silently).
SEAWAY_HOSTILE_ROUNDS=N runs N seeded rounds."""

import numpy as np
import pytest

import seaway
from seaway.vessel import load
from support.forecasts import forecast
from support.hostile import ROUNDS, Judge, run_cli
from support.seasons import channel_season
from support.sigrid import write_chart

pytest.importorskip("pyogrio")
pytest.importorskip("rasterio")
pytestmark = pytest.mark.cli

MAGIC = [
    b"\x89PNG\r\n\x1a\n",
    b"CDF\x01\x00\x00\x00\x00",
    b"\x89HDF\r\n\x1a\n",
    b"II*\x00\x08\x00\x00\x00",
    b"SQLite format 3\x00",
    b"PK\x03\x04",
    b"\x00\x00\x27\x0a\x00\x00\x00\x00",
    b"GRIB\x00\x00\x00\x01",
]
A, B = (70.5, 21.0), (71.5, 28.0)  # on the cost charts and the SIGRID-3 chart
WEST, EAST = (70.5, 60.1), (70.5, 65.9)  # on the season (support.seasons.channel_season)
SHIP = 'name = "x"\nservice_speed_kn = 12\nice_class = "Arc4"\ndraft_m = 9\nbeam_m = 20\n'
BAD_VALUES = [
    "1e30",
    "-1",
    "nan",
    "inf",
    '"fast"',
    "[]",
    "{}",
    "true",
    "1" + "0" * 400,
    '"Arc99"',
    "[1e30, 2]",
]


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    import rasterio
    import shapely
    import xarray as xr

    d = tmp_path_factory.mktemp("whole")
    lat, lon = np.arange(72.0, 69.99, -0.1), np.arange(20.0, 30.01, 0.25)
    cost = xr.Dataset(
        {"cost": (("lat", "lon"), np.random.default_rng(1).uniform(1, 3, (lat.size, lon.size)))},
        coords={"lat": lat, "lon": lon},
    )
    cost.to_netcdf(d / "chart.nc", format="NETCDF4")
    cost.to_netcdf(d / "classic.nc", format="NETCDF3_CLASSIC")
    with rasterio.open(
        d / "chart.tif",
        "w",
        driver="GTiff",
        height=lat.size,
        width=lon.size,
        count=1,
        dtype="float64",
        crs="EPSG:4326",
        transform=rasterio.Affine(0.25, 0.0, 19.875, 0.0, -0.1, 72.05),
    ) as dst:
        dst.write(cost.cost.values, 1)
    ice = [
        (shapely.box(19, 69, 31, 73), {"POLY_TYPE": "I", "CT": "92", "SA": "87"}),
        (shapely.box(24, 70.8, 25, 73), {"POLY_TYPE": "L"}),
    ]
    write_chart(d / "sigrid.shp", ice)
    import pyogrio.raw

    meta, _, wkb, fields = pyogrio.raw.read(d / "sigrid.shp")
    pyogrio.raw.write(
        d / "sigrid.gpkg",
        wkb,
        fields,
        meta["fields"],
        crs="EPSG:4326",
        geometry_type="Polygon",
        driver="GPKG",
    )
    channel_season([(0, (70.4, 70.6, 62.5, 63.0), 10.0, 91.0)], days=2).to_netcdf(d / "season.nc")
    forecast(shape=(21, 31), frames=3, lat0=70.0, lon0=20.0, step=0.1, hs=2.0).to_netcdf(d / "waves.nc")
    (d / "ship.toml").write_text(SHIP)
    return d


def _chart_route(path):
    kw = {"grid": (69, 73, 19, 31, 0.1)} if path.suffix in (".shp", ".gpkg") else {}
    chart = seaway.open_chart(path, **kw)
    return chart.route(A, B, vessel="Arc7" if kw else None).cost


CASES = {
    ".nc": (_chart_route, lambda p: ["route", str(p), "--from", "70.5,21", "--to", "71.5,28", "-q"]),
    ".tif": (_chart_route, lambda p: ["route", str(p), "--from", "70.5,21", "--to", "71.5,28", "-q"]),
    ".shp": (
        _chart_route,
        lambda p: [
            "route",
            str(p),
            "--from",
            "70.5,21",
            "--to",
            "71.5,28",
            "--vessel",
            "Arc7",
            "--grid",
            "69,73,19,31,0.1",
            "-q",
        ],
    ),
    ".gpkg": (
        _chart_route,
        lambda p: [
            "season",
            f"2026-07-01={p}",
            "--from",
            "70.5,21",
            "--to",
            "71.5,28",
            "--vessel",
            "Arc7",
            "--grid",
            "69,73,19,31,0.1",
            "-q",
        ],
    ),
    "season": (
        lambda p: seaway.open_season(p).route(WEST, EAST, vessel="Arc4").cost,
        lambda p: ["season", str(p), "--from", "70.5,60.1", "--to", "70.5,65.9", "--vessel", "Arc4", "-q"],
    ),
    "waves": (
        lambda p: seaway.open_forecast(p).route((70.5, 21.0), (71.5, 22.5)).cost,
        lambda p: ["route", "--forecast", str(p), "--from", "70.5,21", "--to", "71.5,22.5", "-q"],
    ),
    ".toml": (
        lambda p: load(p).vessel.speed_kn,
        lambda p: ["route", "kara", "--from", "70.3,58.49", "--to", "70.5,60", "--vessel-file", str(p), "-q"],
    ),
}


def _kind(name):
    return name.split(".")[0] if name.split(".")[0] in CASES else "." + name.split(".")[-1]


def _break(data, how, rng):
    if how == "empty":
        return b""
    if how == "truncated":
        return data[: int(len(data) * rng.uniform(0.05, 0.99))]
    if how == "flipped":
        b = bytearray(data)
        for i in rng.integers(0, len(b), int(rng.integers(1, 40))):
            b[i] ^= 1 << int(rng.integers(0, 8))
        return bytes(b)
    if how == "magic":
        m = MAGIC[rng.integers(len(MAGIC))]
        return m + data[len(m) :]
    return rng.bytes(len(data))  # garbage


@pytest.mark.parametrize("seed", range(ROUNDS))
def test_broken_files_get_one_line_errors_never_a_partial_read(files, tmp_path, seed):
    rng = np.random.default_rng(2900 + seed)
    judge = Judge()
    names = [
        "chart.nc",
        "classic.nc",
        "chart.tif",
        "sigrid.shp",
        "sigrid.gpkg",
        "season.nc",
        "waves.nc",
        "ship.toml",
    ]
    whole = {name: CASES[_kind(name)][0](files / name) for name in names}
    for k in range(28):
        name = names[k % len(names)]
        how = ["empty", "truncated", "truncated", "flipped", "magic", "garbage"][rng.integers(6)]
        folder = tmp_path / f"{k}"
        folder.mkdir()
        for part in files.glob(name.split(".")[0] + ".*"):
            (folder / part.name).write_bytes(part.read_bytes())
        target = folder / name
        if name.endswith(".shp"):
            target = target.with_suffix([".shp", ".shx", ".dbf", ".prj"][rng.integers(4)])
        target.write_bytes(_break(target.read_bytes(), how, rng))
        path = folder / name
        api, cli = CASES[_kind(name)]
        label = f"seed {seed}: {name} {how} ({target.suffix})"
        value = judge(f"{label}, API", lambda: api(path))
        # (a text file has no length to check: a vessel file cut after "= 1" of "= 12" is valid)
        if value is not None and how == "truncated" and value != whole[name] and not name.endswith(".toml"):
            judge.fault(label, f"read in part, silently: {value} against {whole[name]} for the whole file")
        run_cli(judge, f"{label}, CLI", cli(path))
    judge.verdict(at_least=10)


@pytest.mark.parametrize("seed", range(ROUNDS))
def test_hostile_vessel_files_get_one_line_errors(tmp_path, seed):
    rng = np.random.default_rng(3000 + seed)
    judge = Judge()
    fields = [
        "draft_m",
        "ukc_m",
        "service_speed_kn",
        "displacement_t",
        "length_m",
        "beam_m",
        "max_wave_m",
        "speed_range_kn",
        "ice_class",
        "name",
        "draught_m",
        "speed_loss",
        "outside_validity",
    ]
    for k in range(30):
        text = SHIP + "".join(
            f"{fields[i]} = {BAD_VALUES[rng.integers(len(BAD_VALUES))]}\n"
            for i in rng.choice(len(fields), int(rng.integers(1, 3)), replace=False)
        )
        text = {0: text, 1: text.replace("=", ":"), 2: text[: int(rng.integers(1, len(text)))]}[
            int(rng.integers(3))
        ]
        path = tmp_path / f"ship{k}.{['toml', 'json', 'txt'][rng.integers(3)]}"
        path.write_text(text)
        ship = judge(f"seed {seed}: {text!r}", lambda: load(path))
        if ship is not None and not (0 < ship.vessel.speed_kn < 50):
            judge.fault(text, f"accepted a speed of {ship.vessel.speed_kn} kn")
    judge.verdict(at_least=20)
