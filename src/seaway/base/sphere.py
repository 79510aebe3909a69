"""Spherical geometry in numpy (Olovyannikov 2025, eqs. 1-4, in numerically stable form): great-circle
distance, initial course, points along a great circle and at a distance and bearing.

A sphere of R = EARTH_RADIUS_KM (the engine's); angles in degrees; 1 nm = KM_PER_NM km
(seaway.base.units)."""

from __future__ import annotations

from typing import overload

import numpy as np
import numpy.typing as npt

from .units import EARTH_RADIUS_KM
from .units import KM_PER_NM as KM_PER_NM  # part of this API (re-exported)

#: Degrees or km, one per point (the functions take scalars or arrays that broadcast).
Floats = npt.NDArray[np.float64]


@overload
def distance_km(lat1: float, lon1: float, lat2: float, lon2: float) -> float: ...
@overload
def distance_km(
    lat1: npt.ArrayLike, lon1: npt.ArrayLike, lat2: npt.ArrayLike, lon2: npt.ArrayLike
) -> Floats: ...
def distance_km(
    lat1: npt.ArrayLike, lon1: npt.ArrayLike, lat2: npt.ArrayLike, lon2: npt.ArrayLike
) -> float | Floats:
    """Great-circle distance (haversine), km."""
    p1, p2 = np.radians(lat1), np.radians(lat2)
    dp, dl = p2 - p1, np.radians(np.asarray(lon2, float) - lon1)
    a = np.sin(dp / 2) ** 2 + np.cos(p1) * np.cos(p2) * np.sin(dl / 2) ** 2
    km: float | Floats = 2 * EARTH_RADIUS_KM * np.arcsin(np.sqrt(np.clip(a, 0.0, 1.0)))
    return km


@overload
def course_deg(lat1: float, lon1: float, lat2: float, lon2: float) -> float: ...
@overload
def course_deg(
    lat1: npt.ArrayLike, lon1: npt.ArrayLike, lat2: npt.ArrayLike, lon2: npt.ArrayLike
) -> Floats: ...
def course_deg(
    lat1: npt.ArrayLike, lon1: npt.ArrayLike, lat2: npt.ArrayLike, lon2: npt.ArrayLike
) -> float | Floats:
    """Initial great-circle course from point 1 to point 2, degrees true in [0, 360)."""
    p1, p2 = np.radians(lat1), np.radians(lat2)
    dl = np.radians(np.asarray(lon2, float) - lon1)
    y = np.sin(dl) * np.cos(p2)
    x = np.cos(p1) * np.sin(p2) - np.sin(p1) * np.cos(p2) * np.cos(dl)
    course: float | Floats = np.degrees(np.arctan2(y, x)) % 360.0
    return course


def _to_xyz(lat: npt.ArrayLike, lon: npt.ArrayLike) -> Floats:
    p, lam = np.radians(lat), np.radians(lon)
    return np.stack([np.cos(p) * np.cos(lam), np.cos(p) * np.sin(lam), np.sin(p)], axis=-1)


def _from_xyz(v: Floats) -> tuple[Floats, Floats]:
    lat = np.degrees(np.arctan2(v[..., 2], np.hypot(v[..., 0], v[..., 1])))
    lon = np.degrees(np.arctan2(v[..., 1], v[..., 0]))
    return lat, lon


def intermediate(
    lat1: float, lon1: float, lat2: float, lon2: float, fractions: npt.ArrayLike
) -> tuple[Floats, Floats]:
    """Points at the given fractions (0..1) of the great circle from point 1 to point 2
    (spherical linear interpolation); longitudes in [-180, 180]."""
    a, b = _to_xyz(lat1, lon1), _to_xyz(lat2, lon2)
    f = np.asarray(fractions, float)[:, None]
    omega = np.arctan2(np.linalg.norm(np.cross(a, b)), np.dot(a, b))
    if omega < 1e-12:
        v = np.repeat(a[None, :], len(f), axis=0)
    else:
        v = (np.sin((1 - f) * omega) * a + np.sin(f * omega) * b) / np.sin(omega)
    return _from_xyz(v)


@overload
def destination(lat: float, lon: float, course: float, km: float) -> tuple[float, float]: ...
@overload
def destination(
    lat: npt.ArrayLike, lon: npt.ArrayLike, course: npt.ArrayLike, km: npt.ArrayLike
) -> tuple[Floats, Floats]: ...
def destination(
    lat: npt.ArrayLike, lon: npt.ArrayLike, course: npt.ArrayLike, km: npt.ArrayLike
) -> tuple[float, float] | tuple[Floats, Floats]:
    """The point `km` from (lat, lon) along the initial course `course` (degrees true)."""
    p, lam = np.radians(lat), np.radians(lon)
    th, d = np.radians(course), np.asarray(km, float) / EARTH_RADIUS_KM
    p2 = np.arcsin(np.clip(np.sin(p) * np.cos(d) + np.cos(p) * np.sin(d) * np.cos(th), -1, 1))
    lam2 = lam + np.arctan2(np.sin(th) * np.sin(d) * np.cos(p), np.cos(d) - np.sin(p) * np.sin(p2))
    return np.degrees(p2), (np.degrees(lam2) + 180.0) % 360.0 - 180.0


@overload
def wrap_lon(lon: float) -> float: ...
@overload
def wrap_lon(lon: npt.ArrayLike) -> Floats: ...
def wrap_lon(lon: npt.ArrayLike) -> float | Floats:
    """Longitudes in [-180, 180)."""
    return (np.asarray(lon, float) + 180.0) % 360.0 - 180.0


def unwrap_lon(lon: npt.ArrayLike) -> Floats:
    """Longitudes made continuous along a sequence (no jumps of more than 180 degrees)."""
    lon = np.asarray(lon, float)
    if lon.size < 2:
        return lon.copy()
    out: Floats = lon[0] + np.concatenate([[0.0], np.cumsum((np.diff(lon) + 180.0) % 360.0 - 180.0)])
    return out


def rhumb_line_km(
    lat1: float, lon1: float, lat2: float, lon2: float, radius_km: float = EARTH_RADIUS_KM
) -> float:
    """Loxodrome (constant course) distance on a sphere, km."""
    p1, p2 = np.radians(lat1), np.radians(lat2)
    dl = np.radians((lon2 - lon1 + 180.0) % 360.0 - 180.0)
    dpsi = np.log(np.tan(np.pi / 4 + p2 / 2) / np.tan(np.pi / 4 + p1 / 2))
    q = (p2 - p1) / dpsi if abs(dpsi) > 1e-12 else np.cos(p1)
    return float(radius_km * np.hypot(p2 - p1, q * dl))
