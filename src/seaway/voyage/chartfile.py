"""Read a chart file into an OpenChart: NetCDF (xarray), GeoTIFF (rasterio, optional), SIGRID-3
(seaway.ice.sigrid, the [ice] extra) or the built-in chart "kara" (seaway.voyage.chart routes it).

What the chart's cost is: `variable` names it (cost per unit length, NaN or inf impassable);
otherwise a stage-of-development chart (variable `stage_of_development`, or SIGRID `SA`) is an ice
chart, priced for the vessel's ice class by Grinyak et al. 2022's impact; otherwise a sea-ice
concentration (CF sea_ice_area_fraction) is an ice chart whose stage is assumed; otherwise the
file's only 2-D variable is the cost. A variable `land` (or `land_variable`, a CF
land_binary_mask, a ROMS mask) is the land mask."""

from __future__ import annotations

import os

import numpy as np

from ..base.files import open_netcdf, read_geotiff
from ..chart.flags import flags_out, has_flags
from ..errors import ChartError
from ..ice.concentration import DEFAULT_STAGE, concentration_chart, is_concentration
from ..ice.impact import governing_stage
from ..samples import kara_sea
from .chart import ChartOptions, OpenChart
from .projected import project_chart
from .vectorchart import sigrid_chart

NETCDF = (".nc", ".nc4", ".cdf", ".netcdf", ".h5", ".hdf5")
GEOTIFF = (".tif", ".tiff", ".gtiff")
SIGRID = (".shp", ".gpkg", ".e00", ".zip")
#: Variables reported along each leg when the chart has them.
ENVIRONMENT = (
    "sea_ice_concentration",
    "ice_thickness",
    "CT",
    "thickness",
    "depth",
    "wave_height",
    "wind_speed",
)


def read_chart(path, options: ChartOptions, vessel=None, ends=None) -> OpenChart:
    """The OpenChart of a chart file (seaway.open_chart documents the arguments)."""
    notes: list = []
    path = os.fspath(path)
    if path.lower() in ("kara", "builtin:kara"):
        ds, kind = kara_sea(), "built-in synthetic Kara Sea chart"
    else:
        if not os.path.exists(path):
            raise ChartError(f"{path}: no such file")
        ext = os.path.splitext(path)[1].lower()
        if os.path.isdir(path) and ext not in SIGRID:
            raise ChartError(
                f"{path} is a directory; give a chart file (NetCDF, GeoTIFF or SIGRID-3) inside it"
            )
        if ext in GEOTIFF:
            return _geotiff(path, options, vessel)
        try:
            if ext in SIGRID:
                ds, kind = sigrid_chart(path, options.grid, ends, notes), "SIGRID-3 chart"
            else:
                formats = f"NetCDF ({', '.join(NETCDF)}), GeoTIFF ({', '.join(GEOTIFF)}) or SIGRID-3 ({', '.join(SIGRID)})"
                ds, kind = open_netcdf(path, f"charts are {formats}", ChartError), "NetCDF chart"
        except ChartError:
            raise
        except ValueError as exc:
            raise ChartError(str(exc)) from None
    return _from_dataset(ds, path, f"{kind} {path}", options, vessel, notes)


def _from_dataset(ds, path, description, options, vessel, notes) -> OpenChart:
    variable, land_variable = options.variable, options.land_variable
    if ds.sizes.get("time", 1) > 1 and any(n in ds for n in ("SA", "CT", "stage_of_development")):
        raise ChartError(
            f"{path} is a season of {ds.sizes['time']} ice charts (a time axis): route through it with "
            "`seaway season FILE` (seaway.open_season: the ice changes during the voyage), or select one chart"
        )
    if ds.sizes.get("time", 1) == 1 and "time" in ds.dims:
        ds = ds.isel(time=0)
    land_name = land_variable or _land_name(ds)
    if land_variable and land_variable not in ds:
        raise ChartError(f"{path} has no variable {land_variable!r}; it has {sorted(ds.data_vars)}")
    land = _land(ds[land_name], notes) if land_name else None
    if variable and variable not in ds:
        raise ChartError(f"{path} has no variable {variable!r}; it has {sorted(ds.data_vars)}")
    out = OpenChart(path, description, options, layers=ds, vessel=vessel)
    source = None  # the file's variable the cost comes from (its grid mapping, its flags)
    conc = [n for n in ds.data_vars if is_concentration(ds[n]) and ds[n].ndim >= 2]
    staged = "stage_of_development" in ds or "SA" in ds
    if (variable and is_concentration(ds[variable])) or (not variable and conc and not staged):
        name = variable or _pick_concentration(path, ds, conc)
        source = _two_d(ds[name], notes)
        try:
            ice, assumed = concentration_chart(
                source,
                stage=options.assume_stage or DEFAULT_STAGE,
                land=None if land is None else land.values,
            )
        except ValueError as exc:
            raise ChartError(f"{path}: {exc}") from None
        notes += assumed
        out.layers, land, out.ice = ice, ice["land"], "concentration"
        out.concentration = name
        out.environment["CT"] = ice["CT"]  # reported along the legs, drawn in the WMO colours
        out.description += f", {name} as an ice chart (Grinyak et al. 2022's impact for the class)"
    elif variable or not staged:
        if vessel:
            raise ChartError(
                "give either --variable (a cost raster) or --vessel (an ice class applied to the chart's "
                "stage of development), not both"
                if variable
                else f"{path} has no stage_of_development (or SIGRID SA) variable to apply --vessel to; "
                "give the cost with --variable instead"
            )
        if not variable:
            two_d = [n for n in ds.data_vars if n != land_name and ds[n].ndim >= 2]
            if len(two_d) != 1:
                raise ChartError(
                    f"{path}: which variable is the cost? name it with --variable, one of {sorted(map(str, two_d))}"
                )
            variable = two_d[0]
        source = out.fixed_cost = _two_d(ds[variable], notes)
        out.description += f", cost = {variable}"
        if has_flags(source):
            flagged = flags_out(source)  # CF flags are never costs: land, or impassable
            out.fixed_cost = flagged.values
            notes += flagged.notes
            if flagged.land is not None:
                land = flagged.values.copy(data=flagged.land | (False if land is None else land.values))
    else:
        out.ice = "sigrid" if "SA" in ds and "stage_of_development" not in ds else "stage"
        if out.ice == "stage":
            out.layers = ds.assign(stage_of_development=_two_d(ds.stage_of_development, notes))
        out.description += ", ice impact for the class (Grinyak et al. 2022)"
        # along the legs and on the maps: the stage that governs (SIGRID-3: SA, open and bergy
        # water ice free, fast ice's stated stage) and the form of ice (fast ice)
        stage = (
            out.layers.stage_of_development
            if out.ice == "stage"
            else governing_stage(ds, fast_ice=options.fast_ice)
        )
        notes += [f"assumed: {a}" for a in stage.attrs.get("assumptions", ())]
        out.environment["stage_of_development"] = stage
        if "FA" in ds:
            out.environment["FA"] = ds["FA"]
    out.land = land
    for name in ENVIRONMENT:
        if name in ds and ds[name].ndim >= 2:
            out.environment[name] = _two_d(ds[name], [])
    if source is not None:
        try:  # a projected chart with a CF grid mapping: routed in km, ends and outputs in lat/lon
            project_chart(out, ds, source)
        except ValueError as exc:
            raise ChartError(str(exc)) from None
    if out.grid is None:
        out.grid = out.fixed_cost if out.fixed_cost is not None else _template(out.layers)
    out.date = _date(ds)
    out.notes = notes + out.notes
    return out


def _template(layers):
    """A 2-D layer of an ice chart: its grid."""
    name = next(n for n in ("stage_of_development", "SA", "CT") if n in layers)
    da = _two_d(layers[name], [])
    return da.drop_vars([c for c in da.coords if c not in da.dims])


def _date(ds) -> str:
    """The chart's date as YYYY-MM-DD (HH:MM when not midnight), or ""."""
    t = ds.coords.get("time") if "time" in ds.coords else None
    text = ""
    if t is not None and t.size >= 1 and np.issubdtype(t.dtype, np.datetime64):
        text = str(np.datetime_as_string(np.asarray(t.values).ravel()[0], unit="m"))
    elif ds.attrs.get("time_coverage_start"):
        text = str(ds.attrs["time_coverage_start"])[:16]
    return text.replace("T00:00", "").replace("T", " ")


def _land_name(ds):
    """The land mask's variable: `land`, else a CF land_binary_mask or a ROMS-style mask."""
    if "land" in ds:
        return "land"
    for name, v in ds.data_vars.items():
        std = str(v.attrs.get("standard_name", ""))
        if v.ndim >= 2 and (
            std == "land_binary_mask"
            or (std == "area_type" and "land" in str(v.attrs.get("long_name", "")).lower())
        ):
            return name
    return None


def _land(da, notes):
    """A land mask DataArray (True = land): 0/1 with 1 = land, or ROMS's option_0 = land."""
    da = _two_d(da, notes)
    if str(da.attrs.get("option_0", "")).lower() == "land":  # ROMS: 0 land, 1 water
        notes.append(f"land = {da.name} == 0 (its option_0 is land)")
        return da == 0
    return da.astype(bool)


def _pick_concentration(path, ds, names):
    main = ds.attrs.get("cdr_variable")
    if main in names:
        return main
    if len(names) == 1:
        return names[0]
    raise ChartError(
        f"{path} has several sea-ice concentrations ({', '.join(map(str, names))}); name one with --variable"
    )


def _two_d(da, notes):
    extra = [d for d in da.dims if da.sizes[d] > 1 and d not in da.dims[-2:]]
    if da.ndim > 2:
        sel = {d: 0 for d in da.dims[:-2]}
        if extra:
            notes.append(f"{da.name}: using the first of {', '.join(f'{d}={da.sizes[d]}' for d in extra)}")
        da = da.isel(sel)
    return da


def _geotiff(path, options, vessel) -> OpenChart:
    if vessel:
        raise ChartError(
            "a GeoTIFF chart is read as a cost raster (band 1); --vessel needs a "
            "stage-of-development chart in NetCDF or SIGRID-3"
        )
    variable = options.variable
    band = int(variable) if variable and str(variable).isdigit() else 1
    try:
        da = read_geotiff(path, band, ChartError)
    except ValueError as exc:
        raise ChartError(str(exc)) from None
    da.name = "cost"
    out = OpenChart(path, f"GeoTIFF {path}, band {band}", options)
    out.fixed_cost = out.grid = da
    return out
