"""An ice chart from a sea-ice concentration field alone (passive-microwave products such as
NSIDC's G02202 climate data record, OSI SAF, or an ocean model's aice).

A concentration says how much ice, not which: the stage of development a vessel class is judged
by must be assumed. `concentration_chart` makes that assumption explicit and returns it with the
chart, so the caller can say it (the command line prints it on stderr):

- pixels whose concentration is below `open_water` (0.15 by default: the 15 % edge NSIDC and
  OSI SAF use for ice extent) are ice-free (CT 0, WMO stage 55);
- every other pixel holds ice of the assumed `stage` (WMO code; default 93, thick first-year ice,
  the ice of the Kara and Laptev Seas in winter) at the measured concentration in tenths;
- CF flags (land, coast, lakes; pole hole, missing) come out as land or unknown
  (seaway.chart.flags), never as concentrations."""

from __future__ import annotations

import numpy as np

from ..chart.flags import flags_out
from ..errors import SeawayError
from .codes import stage_name

#: CF standard name of a concentration field.
STANDARD_NAME = "sea_ice_area_fraction"
DEFAULT_STAGE = 93
OPEN_WATER = 0.15


def is_concentration(da) -> bool:
    """Is `da` a concentration field (CF standard name sea_ice_area_fraction, no modifier)?"""
    return str(getattr(da, "attrs", {}).get("standard_name", "")).strip() == STANDARD_NAME


def concentration_chart(conc, *, stage=DEFAULT_STAGE, open_water=OPEN_WATER, land=None):
    """A SIGRID-style Dataset (CT, SA, land; see seaway.ice) from a concentration DataArray
    (fraction 0-1, or percent when its units say so) and the assumptions made, as sentences.

    stage: the WMO stage of development assumed for every ice pixel.
    open_water: the concentration (fraction) below which a pixel is open water.
    land: an optional boolean land mask of the same grid, joined with the flags' land."""
    import xarray as xr

    stage = float(stage)
    if not np.isfinite(stage) or stage_name(stage).startswith("unknown"):
        raise SeawayError(
            f"stage {stage:g} is not a WMO stage of development code; give one, e.g. "
            f"{DEFAULT_STAGE} ({stage_name(DEFAULT_STAGE)})"
        )
    if not 0 <= open_water <= 1:
        raise SeawayError(f"open_water is a fraction (0-1), got {open_water!r}")
    name = str(conc.name)
    flagged = flags_out(conc, name)
    frac = np.asarray(flagged.values.values, dtype=float)
    units = str(conc.attrs.get("units", "")).strip().lower()
    if units in ("%", "percent") or np.nanmax(frac, initial=0) > 1.5:
        frac = frac / 100.0
    frac = np.clip(frac, 0.0, 1.0)
    flag_land = flagged.land if flagged.land is not None else np.zeros(frac.shape, bool)
    is_land = flag_land | (np.asarray(land, bool) if land is not None else False)
    ice = frac >= open_water
    ct = np.where(ice, np.round(frac * 10.0), 0.0)
    ct = np.where(np.isnan(frac) | is_land, np.nan, ct)
    sa = np.where(ice & ~np.isnan(ct), stage, np.nan)
    dims = conc.dims
    ds = xr.Dataset(
        {
            "CT": (dims, ct.astype(np.float32), {"long_name": "total concentration", "units": "0.1"}),
            "SA": (
                dims,
                sa.astype(np.float32),
                {"long_name": "stage of development (assumed)", "units": "1"},
            ),
            "land": (dims, is_land),
        },
        coords=conc.coords,
    )
    assumed = [
        f"{name}: ice of {open_water:g} or more is taken as {stage_name(stage)} (WMO stage "
        f"{stage:g}), an assumption: a concentration does not tell the stage; below "
        f"{open_water:g} is open water"
    ] + flagged.notes
    unknown = np.isnan(ct) & ~is_land
    if unknown.any():
        assumed.append(
            f"{name}: {int(unknown.sum())} pixels of no concentration are unknown ice (impassable)"
        )
    ds.attrs["assumptions"] = "; ".join(assumed)
    return ds, assumed


__all__ = ["STANDARD_NAME", "DEFAULT_STAGE", "OPEN_WATER", "is_concentration", "concentration_chart"]
