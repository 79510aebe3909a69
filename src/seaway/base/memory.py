"""The memory a request needs, estimated before anything is allocated, and refused when the
machine cannot hold it: a grid of 1.5e8 pixels used to grow past 6 GiB and be killed, and one
of 1.5e10 to end in numpy's "Unable to allocate 56.6 GiB" traceback.

The estimate is the pixels times the bytes per pixel of what the request builds (measured peak
resident memory per pixel, rounded up; the figures below and docs/dev/hardening.md). The limit
is the smallest of: SHARE of the machine's physical memory, SHARE of the container's memory
limit (cgroup v2 memory.max or v1 memory.limit_in_bytes), and what the address-space limit
(ulimit -v, RLIMIT_AS) leaves this process. SEAWAY_MEMORY_LIMIT (bytes, or with a suffix: "8G",
"500M") replaces it. The error names the figure, the limit and the fix."""

from __future__ import annotations

import functools
import math
import os
import resource

from ..errors import SeawayError

#: The share of the machine's (or container's) memory one request may take.
SHARE = 0.75
ENV = "SEAWAY_MEMORY_LIMIT"

# Bytes per pixel (peak resident memory per pixel measured on the 2-core machine, rounded up).
#: The engine's search: 8 (accumulated cost) + 1 (predecessor) per query, 1 (clearance to
#: land) per chart (docs/user/engine.md: 9.1-10 B/pixel measured).
SEARCH = 10
#: Routing a chart once it is read: the cost raster (float64), land, the time model's speeds,
#: the search: 60-66 B/pixel measured on the DMI chart (seaway route with --vessel).
ROUTE = 72
#: Rasterising a SIGRID-3 chart: 10 float32 layers, masks, the int32 polygon index and the
#: float64 temporaries: 50-59 B/pixel measured (seaway.ice.sigrid.read_sigrid3).
SIGRID = 64
#: A season of SIGRID-3 charts, per chart, read and routed: 82 B/pixel measured (1-3 DMI charts).
SEASON_CHART = 90
#: A forecast resampled onto a grid, per field and frame, routed: 38-42 B/pixel measured (MET
#: Norway ROMS, 4 fields x 5 frames).
FORECAST_FIELD = 44
#: The synthetic Kara Sea (seaway.samples.kara_sea): 125 B/pixel measured; its season, per day.
KARA = 128
KARA_DAY = 24
#: The synthetic benchmark chart (seaway.samples.synthetic_sea): 69-71 B/pixel measured.
SYNTHETIC = 72


def gib(n: float) -> str:
    """Bytes in words: '56.6 GiB', '750 MiB'."""
    if n >= 2**40:
        return f"{n / 2**40:,.1f} TiB"
    return f"{n / 2**30:.1f} GiB" if n >= 2**30 else f"{n / 2**20:.0f} MiB"


def _parse(text: str) -> int:
    units = {"K": 2**10, "M": 2**20, "G": 2**30, "T": 2**40}
    t = text.strip().upper().removesuffix("IB").removesuffix("B")
    try:
        value = float(t[:-1]) * units[t[-1]] if t and t[-1] in units else float(t)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and value > 0):
        raise SeawayError(f"{ENV} must be a number of bytes such as 8G or 500M, got {text!r}")
    return int(value)


def _read_int(path: str) -> int | None:
    try:
        with open(path) as f:
            text = f.read().strip()
        return int(text) if text.isdigit() else None
    except OSError:
        return None


@functools.lru_cache(maxsize=1)
def _machine() -> tuple[tuple[int, str], ...]:
    """The machine's and the container's memory, read once: (bytes allowed, why) each."""
    physical = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    found = [(int(SHARE * physical), f"{100 * SHARE:.0f} % of this machine's {gib(physical)}")]
    for path in ("/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"):
        cap = _read_int(path)
        if cap is not None and cap < physical:
            found.append((int(SHARE * cap), f"{100 * SHARE:.0f} % of the container's {gib(cap)} limit"))
    return tuple(found)


def limit() -> tuple[int, str]:
    """(the bytes one request may take, a phrase saying where that figure comes from)."""
    if os.environ.get(ENV):
        return _parse(os.environ[ENV]), f"{ENV}={os.environ[ENV]}"
    found = list(_machine())
    soft, _ = resource.getrlimit(resource.RLIMIT_AS)
    if soft != resource.RLIM_INFINITY:
        used = (_read_int_field("/proc/self/statm") or 0) * os.sysconf("SC_PAGE_SIZE")
        left = max(soft - used, 0)
        found.append((left, f"what the {gib(soft)} address-space limit (ulimit -v) leaves: {gib(left)}"))
    return min(found)


def _read_int_field(path: str) -> int | None:
    """The first number of a /proc file (statm: the process's virtual size in pages)."""
    try:
        with open(path) as f:
            return int(f.read().split()[0])
    except (OSError, ValueError, IndexError):
        return None


def check_memory(nbytes: float, what: str, fix: str, error: type[Exception] = SeawayError) -> None:
    """Refuse (`error`) a request of `nbytes` above limit(): "{what} needs about 19.2 GiB, more
    than the 17.6 GiB seaway may take (75 % of this machine's 23.5 GiB); {fix}"."""
    cap, why = limit()
    if nbytes > cap:
        raise error(
            f"{what} needs about {gib(nbytes)}, more than the {gib(cap)} seaway may take ({why}); {fix}"
        )


def fits(bytes_per_pixel: float) -> int:
    """The most pixels limit() allows at `bytes_per_pixel`."""
    return int(limit()[0] // bytes_per_pixel)


def coarser(pixels: float, bytes_per_pixel: float) -> float:
    """The factor by which a grid's resolution must grow (each axis) for `pixels` to fit."""
    return math.sqrt(pixels * bytes_per_pixel / max(limit()[0], 1)) * 1.02


def check_shape(
    rows: int, cols: int, bytes_per_pixel: float, what: str, fix: str, error: type[Exception]
) -> None:
    """check_pixels for an array of `rows` x `cols` whose shape the caller chooses; the fix
    ends with a shape that fits, e.g. "give a smaller shape, e.g. (567, 567)"."""
    f = coarser(rows * cols, bytes_per_pixel)
    fix += f", e.g. ({int(rows / f)}, {int(cols / f)})" if f > 1 else ""
    check_pixels(rows, cols, bytes_per_pixel, what, fix, error)


def check_pixels(
    rows: float,
    cols: float,
    bytes_per_pixel: float,
    what: str,
    fix: str,
    error: type[Exception] = SeawayError,
) -> None:
    """check_memory for a grid of rows x cols pixels at `bytes_per_pixel`; `what` is said as
    "{what} of R x C pixels (N)". Counts are floats: a grid too large to allocate its axes is
    refused before they are made."""
    n = float(rows) * float(cols)
    count = f"{n:,.0f}" if n < 1e12 else f"{n:.3g}"
    check_memory(n * bytes_per_pixel, f"{what} of {rows:,.0f} x {cols:,.0f} pixels ({count})", fix, error)
