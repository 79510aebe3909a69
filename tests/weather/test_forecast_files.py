"""Bad forecast files give errors that say what is wrong with which file: truncated or malformed
NetCDF, GRIB without cfgrib. (The command line's bad charts and interrupts: cli/test_cli_route.py;
bad SIGRID-3 files: ice/test_sigrid_files.py; atomic exports: output/test_route_export.py.)"""

from __future__ import annotations

import sys

import pytest

from seaway.weather.forecast import read_forecast
from support.netcdf import small_dataset as _dataset
from support.netcdf import truncated_netcdf as _truncated


@pytest.mark.parametrize("keep", [0.3, 0.95, 0.9999])
def test_truncated_classic_netcdf_forecast_is_an_error_not_zeros(tmp_path, keep):
    """netCDF-C reads the missing tail of a classic file as zeros; seaway checks the size."""
    bad, size = _truncated(tmp_path, "NETCDF3_64BIT", keep)
    with pytest.raises(
        ValueError,
        match=rf"{bad.name}: the file is truncated: it has "
        rf"{bad.stat().st_size} bytes .* up to byte {size}",
    ):
        read_forecast(bad)


@pytest.mark.parametrize("fmt, keep", [("NETCDF4", 0.5), ("NETCDF4", 0.97), ("NETCDF3_CLASSIC", 0.6)])
def test_truncated_netcdf_forecasts_name_the_file(tmp_path, fmt, keep):
    bad, _ = _truncated(tmp_path, fmt, keep)
    with pytest.raises(ValueError, match=bad.name):
        read_forecast(bad)


@pytest.mark.parametrize(
    "content",
    [b"", b"CDF", b"CDF\x01\x00\x00", b"not a netcdf file" * 9, b"\x89HDF\r\n\x1a\n" + b"\x00" * 40],
)
def test_malformed_netcdf_forecasts_name_the_file(tmp_path, content):
    bad = tmp_path / "bad.nc"
    bad.write_bytes(content)
    with pytest.raises(ValueError, match="bad.nc: "):
        read_forecast(bad)


def test_intact_classic_netcdf_still_reads(tmp_path):
    for fmt in ("NETCDF3_CLASSIC", "NETCDF3_64BIT"):
        path = tmp_path / f"ok-{fmt}.nc"
        _dataset().to_netcdf(path, format=fmt, unlimited_dims=["lat"])
        with read_forecast(path) as ds:
            assert float(ds.cost.sum()) == float(_dataset().cost.sum())


def test_grib_without_cfgrib_names_the_fix(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "cfgrib", None)  # as if cfgrib were not installed
    path = tmp_path / "gfs.grib2"
    path.write_bytes(b"GRIB" + b"\x00" * 100)
    with pytest.raises(
        ImportError, match=r'gfs.grib2: reading GRIB needs cfgrib: pip install "seaway\[grib\]"'
    ):
        read_forecast(path)
