"""Readers of input files that name the file and the fault instead of passing another
library's error on: check_netcdf, open_netcdf (NetCDF through xarray) and read_geotiff
(rasterio).

A truncated classic NetCDF file (CDF-1, CDF-2 or CDF-5) opens without complaint and the
netCDF library returns fill values (zeros) for the bytes past its end: a cost raster would
silently turn into free water. The header states where every variable's data lies, so the
file's size tells whether all of it is there. (NetCDF-4/HDF5 files are checked by HDF5 itself
when opened.) An empty file, or one that is not NetCDF at all (another format's magic bytes),
is named as such; the libraries' own messages are quoted on one line."""

from __future__ import annotations

import os
import struct
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from ..errors import SeawayError
from .validate import one_line

if TYPE_CHECKING:
    import xarray as xr

    #: A file name as the API takes it.
    PathLike = str | os.PathLike[str]

# nc_type -> bytes per value
_SIZES = {1: 1, 2: 1, 3: 2, 4: 4, 5: 4, 6: 8, 7: 1, 8: 2, 9: 4, 10: 8, 11: 8}
_DIMENSION, _VARIABLE, _ATTRIBUTE = 10, 11, 12


class _Header:
    def __init__(self, data: bytes, version: int) -> None:
        self.data, self.pos = data, 4
        self.big = version == 5  # CDF-5: 8-byte counts and sizes
        self.offset64 = version in (2, 5)

    def _take(self, fmt: str) -> int:
        size = struct.calcsize(fmt)
        if self.pos + size > len(self.data):
            raise EOFError
        v: int
        (v,) = struct.unpack_from(fmt, self.data, self.pos)
        self.pos += size
        return v

    def count(self) -> int:
        return self._take(">Q" if self.big else ">I")

    def int32(self) -> int:
        return self._take(">I")

    def offset(self) -> int:
        return self._take(">Q" if self.offset64 else ">I")

    def skip(self, n: int) -> None:
        self.pos += (n + 3) // 4 * 4
        if self.pos > len(self.data):
            raise EOFError

    def name(self) -> None:
        self.skip(self.count())

    def attributes(self) -> None:
        tag, n = self.int32(), self.count()
        if tag not in (0, _ATTRIBUTE):
            raise ValueError("bad attribute list")
        for _ in range(n):
            self.name()
            t = self.int32()
            self.skip(self.count() * _SIZES.get(t, 1))


def _classic_data_end(head: bytes, version: int) -> int | None:
    """The smallest file size holding every variable's data, from a classic header; None if
    the size is indeterminate (a file being streamed)."""
    h = _Header(head, version)
    numrecs = h.count()
    if numrecs in (0xFFFFFFFF, 0xFFFFFFFFFFFFFFFF):
        return None
    tag, n = h.int32(), h.count()
    dims = []
    for _ in range(n):
        h.name()
        dims.append(h.count())
    h.attributes()
    tag, n = h.int32(), h.count()
    if tag not in (0, _VARIABLE):
        raise ValueError("bad variable list")
    fixed_end, records = 0, []
    for _ in range(n):
        h.name()
        ids = [h.count() for _ in range(h.count())]
        h.attributes()
        t = h.int32()
        h.count()  # vsize (capped for large variables): recomputed below
        begin = h.offset()
        size = _SIZES.get(t, 1)
        record = bool(ids) and dims[ids[0]] == 0
        for i in ids[1:] if record else ids:
            size *= dims[i]
        if record:
            records.append((begin, size))
        else:
            fixed_end = max(fixed_end, begin + size)
    if records and numrecs:
        pad: Callable[[int], int] = (lambda s: s) if len(records) == 1 else (lambda s: (s + 3) // 4 * 4)
        recsize = sum(pad(s) for _, s in records)
        fixed_end = max(fixed_end, max(b + (numrecs - 1) * recsize + s for b, s in records))
    return fixed_end


def check_netcdf(path: PathLike, error: type[SeawayError] = SeawayError) -> None:
    """Raise `error` naming `path` when a classic NetCDF file is cut short (or its header
    is unreadable); other files pass unchecked."""
    path = os.fspath(path)
    try:
        with open(path, "rb") as f:
            magic = f.read(4)
            if len(magic) < 4 or magic[:3] != b"CDF" or magic[3] not in (1, 2, 5):
                return
            f.seek(0)
            head = f.read(1 << 20)  # headers are small; a huge one reads as cut short
        have = os.path.getsize(path)
    except OSError:
        return  # the reader reports missing or unreadable files itself
    try:
        need = _classic_data_end(head, magic[3])
    except (EOFError, ValueError, IndexError, struct.error):
        raise error(
            f"{path}: the NetCDF header is damaged or cut short ({have} bytes); "
            "the file is truncated or not NetCDF: download or copy it again"
        ) from None
    if need is not None and have < need:
        raise error(
            f"{path}: the file is truncated: it has {have} bytes but its NetCDF "
            f"header places data up to byte {need}; download or copy it again"
        )


def open_netcdf(
    path: PathLike, hint: str, error: type[SeawayError] = SeawayError, **kwargs: Any
) -> xr.Dataset:
    """xarray.open_dataset(path) after check_netcdf (a truncated classic file would read as
    zeros); any failure becomes `error` (the caller says which kind: ChartError, ForecastError)
    naming the file and `hint` (what the file should be)."""
    import xarray as xr

    path = str(path)
    if not os.path.exists(path):
        raise error(f"{path}: no such file")
    if os.path.isfile(path) and os.path.getsize(path) == 0:
        raise error(
            f"{path}: the file is empty (0 bytes): the download or copy did not finish; fetch it again"
        )
    check_netcdf(path, error)
    try:
        return xr.open_dataset(path, **kwargs)
    except Exception as exc:  # netCDF4/h5netcdf raise many types
        why = _not_netcdf(path) or one_line(exc, 160)
        raise error(f"{path}: cannot read it as NetCDF ({why}); {hint}") from None


#: The first bytes of NetCDF files: classic (CDF-1, -2, -5) and NetCDF-4 (HDF5).
NETCDF_MAGIC = (b"CDF\x01", b"CDF\x02", b"CDF\x05", b"\x89HDF\r\n\x1a\n")


def _not_netcdf(path: str) -> str | None:
    """'it is not NetCDF: it starts ...' when neither a NetCDF magic nor an HDF5 superblock
    (at 0, 512, 1024, ... bytes) is where it should be; None otherwise."""
    try:
        with open(path, "rb") as f:
            head = f.read(8)
            for at in (512, 1024, 2048, 4096):
                f.seek(at)
                if f.read(8) == NETCDF_MAGIC[-1]:
                    return None
    except OSError:
        return None
    if any(head.startswith(m) for m in NETCDF_MAGIC):
        return None
    return f"it is not NetCDF: it starts {head[:4].hex()}, NetCDF files 43444601/02/05 or 89484446"


def read_geotiff(path: PathLike, band: int = 1, error: type[SeawayError] = SeawayError) -> xr.DataArray:
    """One band of a north-up GeoTIFF as a DataArray on pixel-centre coordinates: (lat, lon) when
    its CRS is geographic or absent, else (y, x) with the CRS in attrs["crs"]; nodata -> NaN;
    units, positive and standard_name from the band's tags in attrs. Needs rasterio."""
    import numpy as np
    import xarray as xr

    try:
        import rasterio
    except ImportError:
        raise error(
            f"{path}: reading GeoTIFF needs rasterio: pip install rasterio (or convert it to NetCDF)"
        ) from None
    try:
        src = rasterio.open(path)
    except Exception as exc:  # rasterio's RasterioIOError and others
        raise error(f"{path}: cannot read it as GeoTIFF ({one_line(exc, 160)})") from None
    with src:
        t = src.transform
        if t.b != 0 or t.d != 0:
            raise error(f"{path}: the raster is rotated; warp it north-up first (gdalwarp)")
        if not 1 <= band <= src.count:
            raise error(f"{path} has {src.count} band(s), not band {band}")
        try:
            a = src.read(band).astype(np.float64)
        except Exception as exc:  # rasterio's RasterioIOError on a damaged or cut-short file
            raise error(
                f"{path}: cannot read band {band} ({one_line(exc, 160)}); the file is damaged or cut short: "
                "fetch it again"
            ) from None
        if src.nodata is not None:
            a[a == src.nodata] = np.nan
        tags = {k.lower(): v for k, v in src.tags(band).items()}
        units = src.units[band - 1] if src.units and src.units[band - 1] else tags.get("units", "")
        attrs = {k: tags[k] for k in ("positive", "standard_name") if k in tags}
        if units:
            attrs["units"] = units
        geographic = src.crs is None or src.crs.is_geographic
        if not geographic:
            attrs["crs"] = str(src.crs)
        x = t.c + t.a * (np.arange(src.width) + 0.5)
        y = t.f + t.e * (np.arange(src.height) + 0.5)
        name = (src.descriptions[band - 1] or f"band{band}") if src.descriptions else f"band{band}"
    dims = ("lat", "lon") if geographic else ("y", "x")
    return xr.DataArray(a, dims=dims, coords={dims[0]: y, dims[1]: x}, name=name, attrs=attrs)
