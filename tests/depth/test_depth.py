"""Issue 10 part 2: depth and draft. The real ETOPO5 file in ../shared/data/bathymetry (elevation,
positive up; README.txt's spot values) read, resampled onto chart grids (shallowest node per
pixel where the chart is coarser; also on EPSG:3413), draft + UKC made impassable, the least
depth along a route, paper 002's f1 from the depth, the command line (file conventions and bad
files: test_depth_files.py).

Independent references: the file's own values through xarray, the bottleneck depth between two
ends by bisection on scipy.ndimage.label (the deepest water a ship can sail between them;
4-connected, since the engine never steps across a corner of an impassable pixel)."""

import subprocess
import sys

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway.depth import apply_draft, depth_on_grid, least_depth, open_bathymetry
from seaway.errors import NoRouteError
from seaway.ice import andreeva
from seaway.ice.grids import latlon_grid
from seaway.icenav import pareto
from support.data import SHARED_DATA

ndimage = pytest.importorskip("scipy.ndimage")


ETOPO = SHARED_DATA / "bathymetry" / "etopo5_arctic_60N.nc"
needs_etopo = pytest.mark.needs_data(ETOPO)
OB = {"start": (74.5, 72.0), "end": (69.0, 73.5)}  # Kara Sea -> the Ob Bay (Gulf of Ob)


@pytest.fixture(scope="module")
def etopo():
    return open_bathymetry(ETOPO)


@pytest.fixture(scope="module")
def ob_chart(etopo):
    """Open water (cost 1) on a 0.05 x 0.16 deg grid around the Ob Bay, and its depth."""
    g = latlon_grid(68, 76, 64, 80, (0.05, 0.16))
    cost = xr.DataArray(np.ones(g.shape), dims=("lat", "lon"), coords={"lat": g.y, "lon": g.x})
    return cost, depth_on_grid(etopo, cost)


@needs_etopo
def test_etopo_is_read_as_depth_positive_down_with_the_readme_spot_values(etopo):
    assert "CF attribute positive = 'up'" in etopo.convention and etopo.notes == []
    raw = xr.open_dataset(ETOPO).elevation
    for lat, lon, metres in ((75, 70, 60), (77.9, 104, 85), (86, 0, 4064)):  # README.txt
        assert float(raw.sel(lat=lat, lon=lon, method="nearest")) == -metres
        z = float(etopo.depth.sel(lat=lat, lon=lon, method="nearest"))
        assert z == metres
    # a one-pixel chart centred on a node: linear interpolation gives the node (to the file's
    # longitude spacing of 0.0833341 deg, not exactly 1/12)
    assert float(depth_on_grid(etopo, lat=[75.0], lon=[70.0])[0, 0]) == pytest.approx(60, abs=0.05)
    # 86 N 0 E sits on the file's first column: the wrap at 0/360 is seamless, -10 = 350 E
    assert float(depth_on_grid(etopo, lat=[86.0], lon=[0.0])[0, 0]) == pytest.approx(4064, abs=0.5)
    west = [float(depth_on_grid(etopo, lat=[86.0], lon=[x])[0, 0]) for x in (-10.0, 350.0)]
    assert west[0] == west[1] == pytest.approx(-float(raw.sel(lat=86, lon=350, method="nearest")), abs=1)


@needs_etopo
def test_coarse_pixels_take_the_shallowest_node_inside(etopo):
    g = latlon_grid(74, 76, 68, 72, 1.0)  # 1 deg pixels: 12 x ~12 ETOPO nodes in each
    z = depth_on_grid(etopo, lat=g.y, lon=g.x)
    raw = xr.open_dataset(ETOPO).elevation
    for i, lat in enumerate(g.y):
        for j, lon in enumerate(g.x):
            box = raw.sel(lat=slice(lat - 0.5, lat + 0.5 - 1e-9), lon=slice(lon - 0.5, lon + 0.5 - 1e-9))
            assert float(z[i, j]) == -float(box.max())  # highest elevation = shallowest depth
    assert "shallowest" in z.attrs["resampling"]


def _bottleneck(z, a, b):
    """The deepest `need` for which a and b are joined by water at least `need` deep."""
    lo, hi = 0.0, float(np.nanmax(z))
    for _ in range(40):
        mid = (lo + hi) / 2
        lab, _ = ndimage.label(z >= mid)
        lo, hi = (mid, hi) if lab[a] and lab[a] == lab[b] else (lo, mid)
    levels = np.unique(z[np.isfinite(z)])
    return float(levels[levels >= lo].min())  # the exact depth the bisection closed in on


def _pixel(cost, p):
    return (int(np.abs(cost.lat.values - p[0]).argmin()), int(np.abs(cost.lon.values - p[1]).argmin()))


@needs_etopo
def test_draft_in_the_ob_bay_shallow_draft_passes_deep_draft_refused(ob_chart):
    cost, z = ob_chart
    a, b = _pixel(cost, OB["start"]), _pixel(cost, OB["end"])
    zs, ze = float(z.values[a]), float(z.values[b])
    assert zs > 25 and 9.5 < ze < 10.5  # ETOPO5: 30 m in the Kara Sea, ~10 m in the bay
    neck = _bottleneck(z.values, a, b)
    assert 8.8 < neck < 9.6
    from seaway.depth import deepest_way

    assert deepest_way(cost, None, z, OB["start"], OB["end"]) == pytest.approx(neck, abs=1e-6)
    # 8 m draft + 10 % UKC = 8.8 m: passes; its shallowest water is >= 8.8 and <= the bottleneck
    r = seaway.route(apply_draft(cost, z, 8.0), OB["start"], OB["end"])
    least, where = least_depth(r, z)
    assert 8.8 <= least <= neck + 1e-9
    assert float(z.sel(lat=where[0], lon=where[1])) == least
    # 8.8 m + 10 % = 9.68 m: both ends are deep enough, the way between is not
    with pytest.raises(NoRouteError):
        seaway.route(apply_draft(cost, z, 8.8), OB["start"], OB["end"])
    assert neck < 9.68 < min(zs, ze)


@needs_etopo
def test_paper_002_f1_from_the_bathymetry(ob_chart):
    cost, z = ob_chart
    f1 = andreeva.depth_factor(z, 12.0)
    a = _pixel(cost, OB["start"])
    assert float(f1[a]) == pytest.approx(1 - 12.0 / float(z[a]))
    assert f1.name == "f1" and f1.dims == z.dims
    assert float(f1.values[z.values <= 12].max()) == 0  # too shallow or land: V = 0
    # with the survey correction dL (paper 002 eq. 5: 1.5 m for 500 m line spacing)
    dl = andreeva.survey_correction(500)
    assert float(andreeva.depth_factor(z, 12.0, dl)[a]) == pytest.approx(1 - 12.0 / (float(z[a]) - 1.5))


def run(*args):
    return subprocess.run(
        [sys.executable, "-m", "seaway", *args], capture_output=True, text=True, timeout=300
    )


@pytest.fixture(scope="module")
def ob_file(tmp_path_factory, ob_chart):
    cost, _ = ob_chart
    path = tmp_path_factory.mktemp("ob") / "open_water.nc"
    cost.rename("cost").to_dataset().to_netcdf(path)
    return path


@pytest.mark.slow
@pytest.mark.cli
@needs_etopo
def test_cli_depth_draft_least_depth_and_refusals(ob_file, ob_chart):
    cost, z = ob_chart
    common = ["route", str(ob_file), "--from", "74.5,72", "--to", "69,73.5", "--depth", str(ETOPO)]
    outs = [ob_file.parent / "ob.geojson", ob_file.parent / "ob.csv"]
    done = run(*common, "--draft", "8", "--out", str(outs[0]), "--out", str(outs[1]))
    assert done.returncode == 0, done.stderr
    import json

    props = json.loads(outs[0].read_text())["properties"]
    lat, lon = props["least_depth_at"]
    assert props["least_depth_m"] == pytest.approx(float(z.sel(lat=lat, lon=lon)), abs=1e-9)
    rows = [x for x in outs[1].read_text().splitlines() if not x.startswith("#")]  # '#': the head
    header = rows[0].split(",")
    assert header[-2:] == ["depth_mean", "depth_min"]  # the least depth of each leg
    legs = [line.split(",") for line in rows[2:]]
    assert min(float(r[-1]) for r in legs) == pytest.approx(props["least_depth_m"], abs=0.05)
    assert "draft 8 m + UKC 0.8 m = 8.8 m needed" in done.stderr
    assert "elevation positive up (CF attribute positive = 'up')" in done.stderr
    line = next(s for s in done.stdout.splitlines() if s.startswith("least depth"))
    least = float(line.split()[2])
    neck = _bottleneck(z.values, _pixel(cost, OB["start"]), _pixel(cost, OB["end"]))
    assert 8.8 <= least <= neck + 0.05
    # deep draft: the end itself is too shallow; the message names the depth and the way out
    deep = run(*common, "--draft", "12")
    assert deep.returncode == 1 and deep.stdout == ""
    assert (
        "end 69,73.5 is on an impassable pixel (too shallow: depth 10.0 m < draft 12 m + UKC "
        "1.2 m)" in deep.stderr
    )
    assert "the nearest point the ship may use is" in deep.stderr
    far = run(*common, "--draft", "12", "--snap")  # the nearest deep water is 241 km away
    assert far.returncode == 1 and "farther than --snap-km 20" in far.stderr
    snapped = run(*common, "--draft", "12", "--snap", "--snap-km", "300")
    assert snapped.returncode == 0, snapped.stderr
    moved = snapped.stderr.split("moved ")[1]
    lat, lon = (float(v) for v in moved.split(" to ")[1].split(" ")[0].split(","))
    assert float(z.sel(lat=lat, lon=lon, method="nearest")) >= 13.2
    # ends deep enough, the way not: no route, exit 1
    mid = run(*common, "--draft", "8.8")
    assert mid.returncode == 1 and "no route" in mid.stderr
    assert (
        f"the deepest water joining the ends is {neck:.1f} m, less than draft 8.8 m + UKC "
        f"0.88 m = 9.68 m: a draft of at most {np.floor(neck / 1.1 * 10 + 1e-6) / 10:.1f} m (with the "
        "default UKC of 10 %) gets through"
    ) in mid.stderr
    assert (
        f"at most {np.floor((neck - 0.5) * 10 + 1e-6) / 10:.1f} m (with this UKC)"
        in run(*common, "--draft", "9.5", "--ukc", "0.5").stderr
    )
    # a draft without a bathymetry, a UKC without a draft
    assert (
        "--draft and --ukc need --depth FILE"
        in run("route", str(ob_file), "--from", "74.5,72", "--to", "69,73.5", "--draft", "8").stderr
    )
    assert "--ukc needs --draft" in run(*common, "--ukc", "1").stderr
    junk = ob_file.parent / "junk.nc"
    junk.write_bytes(b"\x89HDF\r\n\x1a\n truncated")
    bad = run(
        "route", str(ob_file), "--from", "74.5,72", "--to", "69,73.5", "--depth", str(junk), "--draft", "8"
    )
    assert bad.returncode == 1 and "junk.nc" in bad.stderr and "Traceback" not in bad.stderr


@needs_etopo
def test_paper_002_time_route_with_f1_from_depth_keeps_out_of_shallows(ob_chart):
    """V = F V0 with F = f1(depth) (open water: f2 = f3 = 1): the fastest route's time is the
    sum of step lengths over F V0, it never enters water shallower than the draft, and a draft
    above the Ob Bay's bottleneck depth finds no route (f1 = 0 there means V = 0)."""
    cost, z = ob_chart
    a, b = _pixel(cost, OB["start"]), _pixel(cost, OB["end"])
    neck = _bottleneck(z.values, a, b)
    F = andreeva.depth_factor(z, 7.0)
    found = pareto.pareto_routes(F, OB["start"], OB["end"], v0_kn=12, thresholds=[1e-9])
    r = found[0].route
    assert found[0].safety == pytest.approx(float(F.values[r.pixels[:, 0], r.pixels[:, 1]].min()))
    assert float(z.values[r.pixels[:, 0], r.pixels[:, 1]].min()) > 7.0
    # the time is the engine's max-rule sum: each step's length / (min F of its two ends * V0)
    lat, lon = cost.lat.values[r.pixels[:, 0]], cost.lon.values[r.pixels[:, 1]]
    geod = pytest.importorskip("pyproj").Geod(a=6371008.8, b=6371008.8)
    km = geod.inv(lon[:-1], lat[:-1], lon[1:], lat[1:])[2] / 1000
    f = F.values[r.pixels[:, 0], r.pixels[:, 1]]
    hours = np.sum(km / (np.minimum(f[:-1], f[1:]) * 12 * 1.852))
    assert found[0].time == pytest.approx(hours, rel=1e-9)
    with pytest.raises(NoRouteError):
        pareto.pareto_routes(
            andreeva.depth_factor(z, neck + 0.05), OB["start"], OB["end"], v0_kn=12, thresholds=[1e-9]
        )


@needs_etopo
def test_depth_on_a_polar_stereographic_grid_is_the_shallowest_node_in_each_pixel(etopo):
    pyproj = pytest.importorskip("pyproj")
    shapely = pytest.importorskip("shapely")
    from seaway.ice.grids import projected_grid

    x0, y0 = (v / 1000 for v in pyproj.Transformer.from_crs(4326, 3413, always_xy=True).transform(70, 75))
    x0, y0 = round(x0 / 20) * 20, round(y0 / 20) * 20
    g = projected_grid("EPSG:3413", x0 - 100, x0 + 100, y0 - 100, y0 + 100, 20)  # 10 x 10, 20 km
    like = xr.DataArray(np.ones(g.shape), dims=g.dims(), coords=g.coords(), attrs={"crs": g.crs})
    z = depth_on_grid(etopo, like)
    assert z.dims == ("y", "x") and "shallowest" in z.attrs["resampling"]
    raw = xr.open_dataset(ETOPO).elevation.sel(lat=slice(71, 79), lon=slice(55, 85))
    lon, lat = np.meshgrid(raw.lon.values, raw.lat.values)
    nx, ny = pyproj.Transformer.from_crs(4326, 3413, always_xy=True).transform(lon, lat)
    for i, yc in enumerate(g.y):
        for j, xc in enumerate(g.x):
            box = shapely.box((xc - 10) * 1000, (yc - 10) * 1000, (xc + 10) * 1000, (yc + 10) * 1000)
            inside = shapely.contains_xy(box, nx, ny)  # nodes on a pixel's edge are not used
            assert inside.sum() >= 4
            assert float(z[i, j]) == -float(raw.values[inside].max())
    with pytest.raises(ValueError, match="no CRS"):
        depth_on_grid(etopo, like.assign_attrs(crs=None))
