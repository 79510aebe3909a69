"""Bad SIGRID-3 files say what is wrong with which file: missing fields, broken geometries, a
wrong or missing CRS, no features (moved from test_bad_files.py)."""

import warnings

import numpy as np
import pytest


def _sigrid(tmp_path, name, geoms, fields, crs="EPSG:4326", gtype="Polygon"):
    pyogrio = pytest.importorskip("pyogrio")
    shapely = pytest.importorskip("shapely")
    path = tmp_path / name
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", "'crs' was not provided", UserWarning)  # on purpose
        pyogrio.raw.write(
            str(path),
            np.array(shapely.to_wkb(geoms), dtype=object),
            [np.asarray(v, dtype=object) for v in fields.values()],
            fields=list(fields),
            geometry_type=gtype,
            crs=crs,
            driver="GPKG" if name.endswith(".gpkg") else "ESRI Shapefile",
        )
    return path


@pytest.fixture
def grid():
    pytest.importorskip("rasterio")
    from seaway.ice.grids import latlon_grid

    return latlon_grid(60, 70, -60, -40, (0.5, 0.5))


ICE = {"CT": ["92"], "SA": ["87"], "POLY_TYPE": ["I"]}


def _read(path, grid):
    from seaway.ice.sigrid import read_sigrid3

    return read_sigrid3(str(path), grid)


def test_sigrid_with_a_broken_polygon_is_repaired_and_read(tmp_path, grid):
    import shapely

    bowtie = shapely.Polygon([(-58, 61), (-42, 69), (-42, 61), (-58, 69)])  # self-intersecting
    ds = _read(_sigrid(tmp_path, "bowtie.gpkg", np.array([bowtie]), ICE), grid)
    assert ds.attrs["repaired_polygons"] == 1
    assert float(ds.CT.max()) == 10.0 and 0 < int((~ds.off_chart).sum()) < ds.off_chart.size


@pytest.mark.parametrize(
    "case, message",
    [
        ("no fields", r"none of the SIGRID-3 fields CT, SA, POLY_TYPE is present \(fields: \['NAME'\]\)"),
        ("empty", r"the layer has no features"),
        ("points", r"1 of 1 features are not polygons \(Point\)"),
        ("wrong crs", r"none of its 1 polygons falls on the grid .* check the file's CRS \(EPSG:3413\)"),
        ("no crs", r"the file states no CRS and its coordinates .* are not degrees"),
        ("garbage", r"cannot read it as a SIGRID-3 vector file"),
        ("truncated", r"is cut short: 60 bytes, less than a shapefile \(\.shp\)'s 100-byte header"),
        ("no sidecars", r"the shapefile's \.dbf \(its attribute table .*\) is missing"),
    ],
)
def test_bad_sigrid_files_say_what_is_wrong_with_which_file(tmp_path, grid, case, message):
    import shapely

    box = np.array([shapely.box(-58, 61, -42, 69)])
    if case == "no fields":
        path = _sigrid(tmp_path, "c.gpkg", box, {"NAME": ["x"]})
    elif case == "empty":
        path = _sigrid(tmp_path, "c.gpkg", np.array([], dtype=object), {k: [] for k in ICE})
    elif case == "points":
        path = _sigrid(tmp_path, "c.gpkg", np.array([shapely.Point(-50, 65)]), ICE, gtype="Point")
    elif case == "wrong crs":  # degrees labelled as polar stereographic metres
        path = _sigrid(tmp_path, "c.gpkg", box, ICE, crs="EPSG:3413")
    elif case == "no crs":  # projected metres without a .prj
        path = _sigrid(tmp_path, "c.shp", np.array([shapely.box(-2e6, -2e6, 2e6, 2e6)]), ICE, crs=None)
    elif case == "garbage":
        path = tmp_path / "c.gpkg"
        path.write_bytes(b"x" * 200)
    else:
        full = _sigrid(tmp_path, "full.shp", box, ICE)
        path = tmp_path / "c.shp"
        path.write_bytes(full.read_bytes()[:60])
        if case == "truncated":  # with its other parts whole
            for ext in (".dbf", ".shx", ".prj"):
                path.with_suffix(ext).write_bytes(full.with_suffix(ext).read_bytes())
    with pytest.raises(ValueError, match=rf"{path.name}:? {message}"):
        _read(path, grid)
