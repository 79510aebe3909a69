"""A season's layers under their SIGRID-3 names, from the names and units other files use
(seaway.ice.seasongrid.as_season): CF sea_ice_area_fraction in its own units becomes CT in
tenths, sea_ice_thickness becomes `thickness` (m), and a chart's stage_of_development (WMO
codes, 55 ice free: seaway.samples.kara_sea) becomes SA."""

from __future__ import annotations

import xarray as xr

from ..errors import ChartError


def tenths_per_unit(units: object, name: str) -> float:
    """Tenths of concentration per unit of a sea_ice_area_fraction in `units`: "1" or none (a
    fraction) 10, "%" 0.1, "0.1" (tenths) 1, any number u 10 u; ChartError naming the fix else."""
    u = str(units if units is not None else "").strip().lower()
    if u in ("", "1", "fraction"):
        return 10.0
    if u in ("%", "percent", "percentage"):
        return 0.1
    if u == "tenths":
        return 1.0
    try:
        return 10.0 * float(u)
    except ValueError:
        raise ChartError(
            f"the season's {name} (sea_ice_area_fraction) is in units {units!r}, which seaway does not "
            "know: give units '1' (a fraction), '%' or '0.1' (tenths)"
        ) from None


def sigrid_layers(ds: xr.Dataset) -> xr.Dataset:
    """`ds` with CT, thickness and SA from its CF or chart names (see the module), where it has
    none under those names. Concentrations a hair outside 0-10 (models' round-off, 1e-6) are
    clipped; others are left for the range check to refuse."""
    by_std = {v.attrs.get("standard_name"): k for k, v in ds.data_vars.items()}
    if "CT" not in ds and "sea_ice_area_fraction" in by_std:
        name = by_std["sea_ice_area_fraction"]
        ct = ds[name] * tenths_per_unit(ds[name].attrs.get("units"), name)
        ct = ct.where(~((ct < 0) & (ct >= -0.01)), 0.0).where(~((ct > 10) & (ct <= 10.01)), 10.0)
        ds = ds.assign(CT=ct)
    if "thickness" not in ds and "sea_ice_thickness" in by_std:
        ds = ds.assign(thickness=ds[by_std["sea_ice_thickness"]])
    if "SA" not in ds and "stage_of_development" in ds:
        stage = ds["stage_of_development"]
        ds = ds.assign(SA=stage.where(stage != 55))
    return ds
