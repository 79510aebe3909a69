"""Which variable of a forecast file plays which role, and how it is marked for the routes:
found by CF standard name (east/north components first, then grid-relative x/y ones), by GRIB
short name, or given; fields with a vertical axis are refused (seaway routes on surface fields)
naming the file's surface alternatives; fields of one file must share one grid; vectors whose
components are grid-relative (GRID_VECTORS, or a variable without a standard name mapped to a
vector role of a projected forecast) keep the grid-relative standard names that
seaway.weather.to_latlon rotates to east/north."""

from __future__ import annotations

from ..chart.cf import GRID_PAIRS, grid_role
from ..chart.roles import STANDARD_NAMES
from ..errors import ForecastError
from .forecast import role_of
from .projected import is_projected


def hit(var) -> tuple[str, str] | None:
    """(role, how it was found) of a variable: role_of, else a grid-relative standard name."""
    found = role_of(var)
    if found:
        return found
    std = var.attrs.get("standard_name")
    g = grid_role(std)
    return (g[0], f"standard name {std}, grid-relative") if g else None


def _levels(var) -> int:
    """How many axes a field has besides time and its two horizontal ones."""
    return max(var.ndim - ("time" in var.dims) - 2, 0)


def pick(ds, wanted: dict, found: dict) -> dict:
    """{role: (variable, how)} of one file: the roles `wanted` maps ({role: name}) whose
    variable it has, then the others by hit(), surface fields before ones with more axes."""
    fields = {r: (n, "given") for r, n in wanted.items() if n in ds.data_vars and r not in found}
    for name, var in sorted(ds.data_vars.items(), key=lambda kv: _levels(kv[1])):
        h = hit(var)
        if h and h[0] not in fields and h[0] not in found and h[0] not in wanted:
            fields[h[0]] = (str(name), h[1])
    return fields


def as_roles(ds, fields: dict, path: str, notes: list):
    """The file's `fields` renamed to their roles, checked (module docstring) and marked; what
    was decided joins `notes`."""
    horizontal = {}
    for role, (name, _) in fields.items():
        var = ds[name]
        if _levels(var):
            extra = [d for d in var.dims if d != "time"][:-2]
            surface = [
                str(n)
                for n, v in ds.data_vars.items()
                if not _levels(v) and (hit(v) or ("",))[0] == role and v.ndim >= 2
            ]
            alt = f"map its surface field with --forecast-variable {role}={surface[0]}, " if surface else ""
            raise ForecastError(
                f"{path}: {name} ({role}) has a vertical axis {extra[0]!r} "
                f"({var.sizes[extra[0]]} levels): seaway routes on surface fields; {alt}or cut "
                f"one level first (e.g. ncks -d {extra[0]},0 or cdo sellevidx,1)"
            )
        horizontal[role] = (name, tuple(d for d in var.dims if d != "time"))
    grids = {dims for _, dims in horizontal.values()}
    if len(grids) > 1:
        (r1, (n1, d1)), (r2, (n2, d2)) = [
            next((r, v) for r, v in horizontal.items() if v[1] == g) for g in list(grids)[:2]
        ]
        raise ForecastError(
            f"{path}: {n1} ({r1}) lies on the grid {d1} but {n2} ({r2}) on {d2}: the fields of "
            "one file must share one grid; move them onto one first (e.g. the model's A-grid "
            "output, or cdo remapbil), or give them as separate --forecast files"
        )
    projected = is_projected(ds)
    keep = [n for n, _ in fields.values()]
    keep += sorted(
        {ds[n].attrs["grid_mapping"] for n in keep if ds[n].attrs.get("grid_mapping") in ds.data_vars}
        - set(keep)
    )
    part = ds[keep].rename({n: r for r, (n, _) in fields.items()})
    relative = {}
    for role, (name, how) in fields.items():
        std = ds[name].attrs.get("standard_name")
        g = grid_role(std)
        if g is not None and g[0] != role:
            raise ForecastError(
                f"{path}: {name} is the grid's {'y' if role.endswith('east') else 'x'} component "
                f"({std}), not {role}: map the other component to {role}"
            )
        relative[role] = role in GRID_PAIRS and (
            g is not None or (projected and how == "given" and std not in STANDARD_NAMES[role])
        )
        std_new = STANDARD_NAMES[role][0]
        if relative[role] and projected:
            std_new = GRID_PAIRS[role][0 if role.endswith("east") else 1]
            why = (
                std
                if g is not None
                else (
                    f"{'standard name ' + std if std else 'no standard name'}, neither east/north nor "
                    "grid x/y: taken as grid-relative, as models write vectors on projected grids"
                )
            )
            notes.append(f"{path}:{name} is grid-relative ({why}): rotated to east/north for {role}")
        elif relative[role]:
            notes.append(f"{path}:{name} ({std}) is on a lat/lon grid: its x axis is east, its y north")
        part[role].attrs["standard_name"] = std_new
    for east, north in (("current_east", "current_north"), ("wind_east", "wind_north")):
        if east in relative and north in relative and relative[east] != relative[north] and projected:
            rel, earth = (east, north) if relative[east] else (north, east)
            raise ForecastError(
                f"{path}: {fields[rel][0]} ({rel}) is grid-relative but {fields[earth][0]} "
                f"({earth}) is not: map both components of one vector (both x/y or both east/north)"
            )
    return part
