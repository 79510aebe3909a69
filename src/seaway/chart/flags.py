"""CF flags and valid ranges are never costs.

A CF variable may mix data with flags: NSIDC's sea-ice concentration (G02202) holds 0-1 where it
measured the ice and 2.51 (pole hole), 2.52 (lake), 2.53 (coast), 2.54 (land) elsewhere, told by
its `flag_values` and `flag_meanings` attributes. Read as costs, those flags would make the land
a cheap sea. Here each flagged pixel is taken out of the data: flags that name land, coast, lakes
or ice shelves become land; every other flag (pole hole, missing data, ...) is impassable. Values
outside `valid_range` (or `valid_min`/`valid_max`) are impassable too. Bit-field variables
(`flag_masks`) are flags, not data, and are refused.

xarray decodes `scale_factor`/`add_offset` but leaves the attributes in packed units; they are
unpacked with the variable's encoding before they are compared (CF 1.11 section 3.5)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from ..errors import ChartError

if TYPE_CHECKING:
    import xarray as xr

#: Words in a flag meaning that make the flagged pixel land.
LAND_WORDS = ("land", "coast", "lake", "ice_shelf", "shelf_ice")


@dataclass
class Flagged:
    """What flags_out found: the data with flags and out-of-range values set to NaN, the pixels
    the flags call land, and one sentence per kind of flag."""

    values: xr.DataArray  # flagged pixels NaN
    land: npt.NDArray[np.bool_] | None = None
    notes: list[str] = field(default_factory=list)


def _unpack(da: xr.DataArray, values: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Attribute values in packed units -> the units of the decoded data."""
    v = np.atleast_1d(np.asarray(values, dtype=float))
    enc = getattr(da, "encoding", {}) or {}
    packed = enc.get("dtype")
    if packed is not None and np.issubdtype(np.dtype(packed), np.integer) and da.dtype.kind == "f":
        v = v * float(enc.get("scale_factor", 1.0)) + float(enc.get("add_offset", 0.0))
    return v


def _is_land(meaning: str) -> bool:
    m = meaning.lower()
    return any(word in m for word in LAND_WORDS)


def has_flags(da: object) -> bool:
    attrs = getattr(da, "attrs", {})
    return any(k in attrs for k in ("flag_values", "flag_masks", "valid_range", "valid_min", "valid_max"))


def flags_out(da: xr.DataArray, name: str = "") -> Flagged:
    """The data of `da` (a DataArray) without its CF flags; see the module's docstring."""
    name = name or str(da.name)
    attrs = da.attrs
    if "flag_masks" in attrs and "flag_values" not in attrs:
        raise ChartError(
            f"{name} is a bit field of flags (CF flag_masks: "
            f"{str(attrs.get('flag_meanings', ''))[:80]}), not a cost or an ice field; "
            "choose a data variable"
        )
    out = Flagged(values=da)
    values = np.asarray(da.values, dtype=float)
    drop = np.zeros(values.shape, dtype=bool)
    if "flag_values" in attrs:
        flags = _unpack(da, attrs["flag_values"])
        meanings = str(attrs.get("flag_meanings", "")).split()
        if len(meanings) != len(flags):
            meanings = [f"flag {f:g}" for f in flags]
        land = np.zeros(values.shape, dtype=bool)
        for flag, meaning in zip(flags, meanings):
            hit = np.isclose(values, flag, rtol=0, atol=1e-6 * max(1.0, abs(flag)))
            if not hit.any():
                continue
            n = int(hit.sum())
            if _is_land(meaning):
                land |= hit
                out.notes.append(f"{name}: {n} pixels flagged {meaning} ({flag:g}) are land")
            else:
                out.notes.append(f"{name}: {n} pixels flagged {meaning} ({flag:g}) are impassable")
            drop |= hit
        if land.any():
            out.land = land
    lo, hi = -np.inf, np.inf
    if "valid_range" in attrs:
        lo, hi = _unpack(da, attrs["valid_range"])[:2]
    lo = float(_unpack(da, attrs["valid_min"])[0]) if "valid_min" in attrs else lo
    hi = float(_unpack(da, attrs["valid_max"])[0]) if "valid_max" in attrs else hi
    tol = 1e-6 * max(1.0, abs(lo), abs(hi)) if np.isfinite(lo) or np.isfinite(hi) else 0.0
    outside = ~drop & np.isfinite(values) & ((values < lo - tol) | (values > hi + tol))
    if outside.any():
        out.notes.append(
            f"{name}: {int(outside.sum())} pixels outside its valid range {lo:g}..{hi:g} are impassable"
        )
        drop |= outside
    if drop.any():
        out.values = da.copy(data=np.where(drop, np.nan, values).astype(values.dtype))
    return out


__all__ = ["Flagged", "LAND_WORDS", "flags_out", "has_flags"]
