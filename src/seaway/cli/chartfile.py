"""Open a chart file for the command line: NetCDF (xarray), GeoTIFF (rasterio, optional),
SIGRID-3 (seaway.ice.sigrid, when installed) or the built-in chart "kara".

The cost raster is chosen as follows: `variable` names it (cost per unit length, NaN or inf
impassable); otherwise a stage-of-development chart (variable `stage_of_development`, or SIGRID
`SA`) is turned into Grinyak et al. 2022's impact for the vessel's ice class; otherwise the file's only
2-D variable is the cost. A variable `land` (or `land_variable`) is the land mask."""

from __future__ import annotations

import os
from dataclasses import dataclass, field

import numpy as np

from ..base.files import open_netcdf, read_geotiff
from ..chart.flags import flags_out, has_flags
from ..ice import chart_impact
from ..ice.codes import stage_name
from ..ice.concentration import DEFAULT_STAGE, concentration_chart, is_concentration
from ..ice.forms import DEFAULT_FAST_ICE, check_fast_ice
from ..ice.impact import governing_stage
from ..samples import ice_impact, kara_sea
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


class ChartError(ValueError):
    """A chart file that cannot be read or used."""


@dataclass
class ChartData:
    cost: object  # xarray.DataArray
    land: object = None
    environment: dict = field(default_factory=dict)
    description: str = ""
    notes: list = field(default_factory=list)
    layers: object = None  # the chart's Dataset (SIGRID-3 CT, SA, ... land): describes the ends
    projection: object = None  # seaway.cli.projected.Projection of a projected chart, else None
    date: str = ""  # the chart's date (its time coordinate or time_coverage_start), if it has one


def open_chart(
    path: str,
    *,
    variable=None,
    vessel=None,
    land_variable=None,
    grid=None,
    ends=None,
    stage=None,
    fast_ice=DEFAULT_FAST_ICE,
) -> ChartData:
    """grid: (south, north, west, east, resolution) in degrees for a SIGRID-3 chart; by default
    a regional grid around `ends` ((lat, lon) start and end; seaway.ice.routegrid), else the
    chart's own extent at 1/1000 of its longer side (geographic charts only).
    stage: the WMO stage assumed for the ice of a concentration-only chart (default 93).
    fast_ice: the stage of fast ice of unknown stage (seaway.ice.forms); what it assumes joins
    the notes."""

    notes: list = []
    if path.lower() in ("kara", "builtin:kara"):
        ds = kara_sea()
        kind = "built-in synthetic Kara Sea chart"
    else:
        if not os.path.exists(path):
            raise ChartError(f"{path}: no such file")
        ext = os.path.splitext(path)[1].lower()
        if os.path.isdir(path) and ext not in SIGRID:
            raise ChartError(
                f"{path} is a directory; give a chart file (NetCDF, GeoTIFF or SIGRID-3) inside it"
            )
        if ext in GEOTIFF:
            return _geotiff(path, variable, vessel)
        if ext in SIGRID:
            try:
                ds, kind = sigrid_chart(path, grid, ends, notes), "SIGRID-3 chart"
            except ValueError as exc:
                raise ChartError(str(exc)) from None
        else:
            try:
                ds = open_netcdf(
                    path,
                    f"charts are NetCDF ({', '.join(NETCDF)}), GeoTIFF "
                    f"({', '.join(GEOTIFF)}) or SIGRID-3 ({', '.join(SIGRID)})",
                )
            except ValueError as exc:
                raise ChartError(str(exc)) from None
            kind = "NetCDF chart"
    out = ChartData(cost=None, description=f"{kind} {path}", layers=ds)
    out.notes += notes
    land_name = land_variable or _land_name(ds)
    if land_variable and land_variable not in ds:
        raise ChartError(f"{path} has no variable {land_variable!r}; it has {sorted(ds.data_vars)}")
    land = _land(ds[land_name], out.notes) if land_name else None
    source = None  # the file's variable the cost comes from (its grid mapping, its flags)
    conc = [n for n in ds.data_vars if is_concentration(ds[n]) and ds[n].ndim >= 2]
    if variable and variable not in ds:
        raise ChartError(f"{path} has no variable {variable!r}; it has {sorted(ds.data_vars)}")
    if (
        variable
        and is_concentration(ds[variable])
        or (not variable and conc and not ("stage_of_development" in ds or "SA" in ds))
    ):
        name = variable or _pick_concentration(path, ds, conc)
        source = _two_d(ds[name], out.notes)
        if not vessel:
            raise ChartError(
                f"{path}: {name} is a sea-ice concentration (CF sea_ice_area_fraction), not a cost "
                "per unit length (open water would cost nothing); give --vessel CLASS (e.g. Arc7) "
                f"to turn it into an ice chart for that class, its ice assumed to be "
                f"{stage_name(stage or DEFAULT_STAGE)} (--assume-stage CODE to change)"
            )
        try:
            ice, assumed = concentration_chart(
                source, stage=stage or DEFAULT_STAGE, land=None if land is None else land.values
            )
        except ValueError as exc:
            raise ChartError(f"{path}: {exc}") from None
        out.notes += assumed
        out.layers, land = ice, ice["land"]
        out.environment["CT"] = ice["CT"]  # reported along the legs, drawn in the WMO colours
        out.cost = chart_impact(ice, vessel)
        out.description += f", {name} as an ice chart for {vessel} (Grinyak et al. 2022)"
    elif variable:
        if vessel:
            raise ChartError(
                "give either --variable (a cost raster) or --vessel (an ice class "
                "applied to the chart's stage of development), not both"
            )
        source = out.cost = _two_d(ds[variable], out.notes)
        out.description += f", cost = {variable}"
    elif "stage_of_development" in ds or "SA" in ds:
        out.cost = _impact(ds, vessel or "Arc7", out.notes, fast_ice)
        out.description += f", ice impact for {vessel or 'Arc7'} (Grinyak et al. 2022)"
        # along the legs and on the maps: the stage that governs (SIGRID-3: SA, open and bergy
        # water ice free, fast ice's stated stage) and the form of ice (fast ice)
        out.environment["stage_of_development"] = (
            _two_d(ds.stage_of_development, []) if "SA" not in ds else governing_stage(ds, fast_ice=fast_ice)
        )
        if "FA" in ds:
            out.environment["FA"] = ds["FA"]
    else:
        two_d = [n for n in ds.data_vars if n != land_name and ds[n].ndim >= 2]
        if len(two_d) != 1:
            raise ChartError(
                f"{path}: which variable is the cost? name it with --variable, one of "
                f"{sorted(map(str, two_d))}"
            )
        if vessel:
            raise ChartError(
                f"{path} has no stage_of_development (or SIGRID SA) variable to apply "
                "--vessel to; give the cost with --variable instead"
            )
        source = out.cost = _two_d(ds[two_d[0]], out.notes)
        out.description += f", cost = {two_d[0]}"
    if source is not None and has_flags(source) and source is out.cost:
        flagged = flags_out(source)  # CF flags are never costs: land, or impassable
        out.cost, out.notes = flagged.values, out.notes + flagged.notes
        if flagged.land is not None:
            land = flagged.values.copy(data=flagged.land | (False if land is None else land.values))
    if land is not None:
        out.land = land
    for name in ENVIRONMENT:
        if name in ds and ds[name].ndim >= 2:
            out.environment[name] = _two_d(ds[name], [])
    if source is not None:
        try:  # a projected chart with a CF grid mapping: routed in km, ends and outputs in lat/lon
            project_chart(out, ds, source)
        except ValueError as exc:
            raise ChartError(str(exc)) from None
    out.date = _date(ds)
    return out


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


def _impact(ds, vessel, notes, fast_ice=DEFAULT_FAST_ICE):
    if "SA" in ds and "stage_of_development" not in ds:
        try:
            u = chart_impact(ds, vessel, fast_ice=fast_ice)
        except ValueError as exc:
            raise ChartError(str(exc)) from None
        notes += [f"assumed: {a}" for a in u.attrs.get("assumptions", ())]
        return u
    try:
        return ice_impact(_two_d(ds.stage_of_development, notes), vessel)
    except ValueError as exc:
        raise ChartError(str(exc)) from None


def _geotiff(path, variable, vessel):
    if vessel:
        raise ChartError(
            "a GeoTIFF chart is read as a cost raster (band 1); --vessel needs a "
            "stage-of-development chart in NetCDF or SIGRID-3"
        )
    band = int(variable) if variable and str(variable).isdigit() else 1
    try:
        da = read_geotiff(path, band)
    except ValueError as exc:
        raise ChartError(str(exc)) from None
    da.name = "cost"
    return ChartData(cost=da, description=f"GeoTIFF {path}, band {band}")


def fast_ice(text: str):
    """argparse type of --fast-ice: 'nearby', 'closed' or a WMO stage code (seaway.ice.forms)."""
    import argparse

    try:
        return check_fast_ice(text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None
