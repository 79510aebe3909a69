"""Readers: SIGRID-3 ice charts (shapefile, GeoPackage: AARI, NIC, CIS, DMI) rasterised onto a
Grid you choose, and NSIDC G02202 gridded sea-ice concentration (NetCDF).

Needs the optional packages pyogrio, shapely, rasterio and pyproj (``pip install
"seaway[ice]"``); the ImportError says so. Output: the ice chart Dataset documented in
seaway.ice (CT, CA-CC in tenths; SA-SC WMO codes; FA-FC form codes (8 = fast ice); free_water
(CT code 01 open water / 02 bergy water); land, ice_shelf, off_chart, polygon). How the forms
are costed (fast ice, bergy water, icebergs): seaway.ice.forms.

What real charts contain, and what the reader does with it:
* codes as text, with or without the leading zero ('1' = '01'), NULL on land: parse_code.
* -9 = not applicable, 99 = unknown concentration -> NaN (unknown: never open water);
  stage 99 (or any non-WMO number) -> 99 (unknown). Non-numeric text -> missing.
* range codes ('57' = 5-7/10, '91' = 9-10/10) -> the `concentration` end ('upper' default).
* POLY_TYPE L (land) and S (ice shelf) -> land = True; W (water) -> CT = 0; N (no data) ->
  all NaN (unknown); I (ice) -> decoded.
* partial concentrations missing while stages are given (DMI charts give SA, SB without CA,
  CB): the part of CT no partial accounts for goes to the first such stage, i.e. the thickest
  (SIGRID-3 orders SA thickest): conservative.
* invalid rings (self-intersections, wrong winding), rings across the antimeridian or around
  a pole -> made valid in the grid's CRS by seaway.ice.geometry (antimeridian, shapely, pyproj).
A pixel takes the polygon containing its centre (all_touched=False; where polygons overlap,
the later one in the file); pixels no polygon covers are off_chart with NaN layers."""

from __future__ import annotations

import warnings

import numpy as np

from ..base.memory import SIGRID, check_pixels
from ..errors import ChartError
from .codes import FORM_CODES, concentration_tenths, form_code, parse_code, stage_code
from .geometry import to_grid_crs, wrap_copies
from .grids import Grid
from .sigridcheck import FIX, check_contents, expected_records, geometries
from .vectorfile import one_line

_STAGES = ("SA", "SB", "SC")
_PARTIALS = ("CA", "CB", "CC")
_FORMS = ("FA", "FB", "FC")
EXTRA = 'pip install "seaway[ice]"'


def _require():
    try:
        import antimeridian  # noqa: F401
        import pyogrio.raw  # noqa: F401
        import pyproj  # noqa: F401
        import rasterio.features  # noqa: F401
        import shapely  # noqa: F401
    except ImportError as exc:
        raise ImportError(
            f"seaway.ice.sigrid needs the optional packages pyogrio, shapely, "
            f"rasterio, pyproj and antimeridian ({exc.name} is missing): {EXTRA}"
        ) from exc


def _decode(fields: dict, n: int, rule: str) -> dict:
    """Per-polygon decoded layers (float64 arrays of length n) and poly types."""
    get = lambda name: fields.get(name, [None] * n)  # noqa: E731
    ptype = np.array([str(v).strip().upper()[:1] if v is not None else "" for v in get("POLY_TYPE")])
    out = {"CT": np.array([concentration_tenths(parse_code(v), rule) for v in get("CT")])}
    for c, s in zip(_PARTIALS, _STAGES):
        out[c] = np.array([concentration_tenths(parse_code(v), rule) for v in get(c)])
        out[s] = np.array([stage_code(v) for v in get(s)])
    # Partials missing for present stages: the remainder of CT goes to the first (thickest).
    known = np.nansum([np.where(np.isnan(out[s]), 0, out[c]) for c, s in zip(_PARTIALS, _STAGES)], 0)
    rest = np.maximum(out["CT"] - known, 0)
    given = np.zeros(n, bool)
    for c, s in zip(_PARTIALS, _STAGES):
        fill = ~np.isnan(out[s]) & np.isnan(out[c])
        out[c] = np.where(fill & ~given, rest, np.where(fill, 0.0, out[c]))
        given |= fill
    for f in _FORMS:
        out[f] = np.array([form_code(v) for v in get(f)])
    ct_code = np.array([parse_code(v) for v in get("CT")])
    out["free_water"] = np.where(ct_code == 1, 1, np.where(ct_code == 2, 2, 0)).astype(np.uint8)
    out["CT"] = np.where(ptype == "W", np.where(np.isnan(out["CT"]), 0.0, out["CT"]), out["CT"])
    blank = np.isin(ptype, ["L", "S", "N"])
    for name in ("CT",) + _PARTIALS + _STAGES + _FORMS:
        out[name] = np.where(blank, np.nan, out[name])
    out["free_water"] = np.where(blank | (ptype == "W"), 0, out["free_water"]).astype(np.uint8)
    out["land"] = np.isin(ptype, ["L", "S"])
    out["ice_shelf"] = ptype == "S"
    return out


def _flag(name: str) -> str:
    return "_".join(name.replace(",", " ").replace("/", "_").split())


def read_sigrid3(path, grid: Grid, *, layer=None, concentration="upper", all_touched=False):
    """Read a SIGRID-3 chart (any vector format GDAL reads: .shp, .gpkg, ...) and rasterise it
    onto `grid` (seaway.ice.grids.latlon_grid or projected_grid). Returns an xarray.Dataset
    (see seaway.ice); its `polygon` layer indexes the file's features in reading order."""
    _require()
    import pyogrio.raw
    import rasterio.features
    import shapely
    import xarray as xr
    from affine import Affine

    check_pixels(
        *grid.shape,
        SIGRID,
        "rasterising a chart onto a grid",
        "give a coarser grid or a smaller box",
        ChartError,
    )
    expected = expected_records(path, layer)  # a shapefile's parts agree (none is cut short)
    try:
        with warnings.catch_warnings(record=True) as said:  # GDAL's notes: damage is named below
            warnings.simplefilter("always")
            meta, _, wkb, field_data = pyogrio.raw.read(path, layer=layer)
    except Exception as exc:  # pyogrio's DataSourceError, DataLayerError, ...
        raise ChartError(f"{path}: cannot read it as a SIGRID-3 vector file ({one_line(str(exc))})") from None
    fields = {str(k).upper(): v for k, v in zip(meta["fields"], field_data)}
    geoms, without = geometries(path, wkb, expected)
    check_contents(path, meta, fields, geoms)
    gdal = sorted({str(w.message) for w in said if "winding order" not in str(w.message)})
    try:
        geoms, repaired = to_grid_crs(geoms, meta["crs"] or "EPSG:4326", grid.crs)
        if grid.geographic:
            shapes = wrap_copies(geoms, grid.x[0], grid.x[-1])
        else:
            shapes = [(g, i) for i, g in enumerate(geoms) if not g.is_empty]
        index = rasterio.features.rasterize(
            shapes,
            out_shape=grid.shape,
            fill=-1,
            dtype="int32",
            transform=Affine(*grid.transform()),
            all_touched=all_touched,
        )
    except (shapely.errors.ShapelyError, ValueError, RuntimeError) as exc:  # GEOS, PROJ, GDAL
        note = f"; GDAL said: {gdal[0]}" if gdal else ""
        raise ChartError(
            f"{path}: its polygons cannot be used ({one_line(str(exc) + note)}); {FIX}"
        ) from None
    n = len(geoms)
    if (index < 0).all():
        box = shapely.total_bounds(geoms)
        raise ChartError(
            f"{path}: none of its {n} polygons falls on the grid (their extent in the grid's CRS "
            f"{grid.crs} is x {box[0]:.6g}..{box[2]:.6g}, y {box[1]:.6g}..{box[3]:.6g}); check the "
            f"file's CRS ({str(meta['crs'] or 'none: read as EPSG:4326')[:80]}) and the grid"
        )
    layers = _decode(fields, n, concentration)
    off = index < 0
    dims = grid.dims()
    data: dict[str, tuple] = {}
    attrs = {
        "CT": ("total concentration", "0.1"),
        "CA": ("partial concentration of SA", "0.1"),
        "CB": ("partial concentration of SB", "0.1"),
        "CC": ("partial concentration of SC", "0.1"),
        "SA": ("stage of development, thickest (WMO code)", "1"),
        "SB": ("stage of development, second (WMO code)", "1"),
        "SC": ("stage of development, third (WMO code)", "1"),
    }
    for name, (long_name, units) in attrs.items():
        values = np.append(layers[name], np.nan)[index].astype(np.float32)
        data[name] = (dims, values, {"long_name": long_name, "units": units})
    for name, whose in zip(_FORMS, _STAGES):
        values = np.append(layers[name], np.nan)[index].astype(np.float32)
        data[name] = (
            dims,
            values,
            {
                "long_name": f"form of ice of {whose} (SIGRID-3 code; 8 fast ice)",
                "units": "1",
                "flag_values": np.array(sorted(FORM_CODES), np.int8),
                "flag_meanings": " ".join(_flag(n) for _, n in sorted(FORM_CODES.items())),
            },
        )
    data["free_water"] = (
        dims,
        np.append(layers["free_water"], 0)[index].astype(np.uint8),
        {
            "long_name": "freely navigable water by its CT code (WMO-No. 259)",
            "flag_values": np.array([0, 1, 2], np.uint8),
            "flag_meanings": "not_coded_so open_water bergy_water",
        },
    )
    for name in ("land", "ice_shelf"):
        data[name] = (dims, np.append(layers[name], False)[index])
    data["off_chart"] = (dims, off, {"long_name": "no chart polygon at the pixel centre"})
    data["polygon"] = (dims, index, {"long_name": "index of the source polygon (-1 none)"})
    ds = xr.Dataset(data, coords=grid.coords())
    ds.attrs.update(
        source=str(path),
        crs=grid.crs,
        source_crs=str(meta["crs"])[:200],
        concentration_rule=concentration,
        polygons=n,
        repaired_polygons=repaired,
        features_without_geometry=without,
        Conventions="CF-1.8",
    )
    return ds


def read_nsidc_g02202(path, grid: Grid | None = None, *, variable="cdr_seaice_conc", stage=None):
    """NSIDC G02202 (v4) sea-ice concentration as an ice chart Dataset: CT (tenths; NaN at the
    pole hole and missing data: unknown), land (flags land, coast, lakes), off_chart, and SA =
    `stage` where CT > 0 if you give one (the product has no stages: assuming one is your
    explicit choice; otherwise SA is absent). On its native 25 km polar stereographic grid (y, x
    in km) or, with `grid`, sampled onto it by nearest neighbour."""
    _require()
    import pyproj
    import xarray as xr

    with xr.open_dataset(path, mask_and_scale=False) as src:
        if variable not in src.data_vars:
            raise _no_variable(path, variable, list(src.data_vars))
        raw = np.asarray(src[variable].squeeze().values).astype(np.int32)
        xs = src["xgrid"].values.astype(float)
        ys = src["ygrid"].values.astype(float)
        crs = src["projection"].attrs.get("proj4text") or "EPSG:3411"
    native = Grid(crs, xs / 1000.0, ys / 1000.0)
    if grid is not None:
        tr = pyproj.Transformer.from_crs(
            pyproj.CRS.from_user_input(grid.crs), pyproj.CRS.from_user_input(crs), always_xy=True
        )
        gx, gy = grid.centres()
        x, y = tr.transform(gx, gy)
        col = np.rint((x - xs[0]) / (xs[1] - xs[0])).astype(np.int64)
        row = np.rint((y - ys[0]) / (ys[1] - ys[0])).astype(np.int64)
        inside = (col >= 0) & (col < len(xs)) & (row >= 0) & (row < len(ys))
        raw = np.where(inside, raw[np.clip(row, 0, len(ys) - 1), np.clip(col, 0, len(xs) - 1)], -1)
    else:
        grid = native
        inside = np.ones(raw.shape, bool)
    ct = np.where((raw >= 0) & (raw <= 100), raw / 10.0, np.nan).astype(np.float32)
    land = np.isin(raw, [252, 253, 254])
    dims = grid.dims()
    data = {
        "CT": (dims, ct, {"long_name": "total concentration", "units": "0.1"}),
        "land": (dims, land, {"long_name": "land, coast or lake (G02202 flags 252-254)"}),
        "off_chart": (dims, ~inside, {"long_name": "outside the product's grid"}),
    }
    if stage is not None:
        sa = np.where(ct > 0, float(stage), np.nan).astype(np.float32)
        data["SA"] = (dims, sa, {"long_name": "assumed stage of development (WMO code)"})
        data["CA"] = (
            dims,
            np.where(ct > 0, ct, np.nan).astype(np.float32),
            {"long_name": "partial concentration of SA", "units": "0.1"},
        )
    ds = xr.Dataset(data, coords=grid.coords())
    ds.attrs.update(
        source=str(path),
        crs=grid.crs,
        product="NSIDC G02202 v4",
        assumed_stage=-1 if stage is None else int(stage),
    )
    return ds


def _no_variable(path, variable, found):
    """The ChartError for a G02202 file without `variable` (e.g. a monthly file, whose
    concentration is cdr_seaice_conc_monthly): the variables found and the one to name."""
    conc = [v for v in found if v.startswith("cdr_seaice_conc")] or [v for v in found if "seaice_conc" in v]
    fix = (
        f'pass variable="{conc[0]}" (seaway route: --variable {conc[0]})'
        if conc
        else "pass variable= the concentration variable (seaway route: --variable NAME)"
    )
    return ChartError(f"{path} has no variable {variable!r}; it has {', '.join(sorted(found))}: {fix}")
