"""Vessel files: a ship's profile in TOML (or JSON), read and validated field by field.

One table of fields (FIELDS); `name` and `service_speed_kn` are required, the rest optional:

    name = "PC6 general cargo ship"
    ice_class = "PC6"                 # Register (Arc4 ... Arc9, Ice1-3) or IACS PC1-PC7
    draft_m = 9.0
    ukc_m = 1.0                       # under-keel clearance
    service_speed_kn = 13.5           # calm-water speed: V0 in ice, the weather routes' speed
    speed_range_kn = [6.0, 15.0]      # the engine settings a fuel route may choose from
    displacement_t = 22000.0
    length_m = 150.0
    beam_m = 23.0
    speed_loss = "khokhlov"           # or "stawave1" (needs calm_resistance_kn) or "none"
    calm_resistance_kn = 700.0
    max_wind_ms = 25.0                # hard limits: never crossed
    max_wave_m = 5.0
    danger_wind_ms = 11.0             # danger zones: avoided while forecast (Sotnikova 2009)
    danger_wave_m = 4.0

    [ice_curve]                       # speed in level ice against its thickness (ice trials)
    thickness_m = [0.0, 1.0, 1.5, 2.1]
    speed_kn = [19.5, 9.0, 5.5, 2.0]

    [fuel]                            # fuel rate by engine setting: a table ...
    speeds_kn = [8.0, 10.0, 12.0, 13.5]
    rates_t_per_h = [0.35, 0.6, 1.0, 1.45]
    # ... or a reference point of the propeller law: reference_speed_kn, reference_rate_t_per_h

    [sources]                         # where each value comes from, or "assumption: ..."
    draft_m = "..."

Every number has a plausible range (RANGES, with the record it is drawn from); a wrong file is
refused naming the file, the field and the fix. The examples shipped with the
package (EXAMPLES; `load(name)` reads them) give a source or an assumption for every value."""

from __future__ import annotations

import difflib
import json
import math
import os
import sys
from importlib import resources
from typing import Any, NoReturn

from ..errors import SeawayError, VesselFileError
from ..ice.classes import get_class
from .ship import SPEED_LOSSES, IceCurve, Vessel

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - the tomli backport on older Pythons
    import tomli as tomllib

#: field -> (kind, what it is and its unit, an example value)
FIELDS = {
    "name": ("text", "the ship's name", '"Arc7 LNG carrier"'),
    "ice_class": ("class", "ice class (Register or IACS Polar Class)", '"Arc7"'),
    "draft_m": ("positive", "draft in metres", "11.8"),
    "ukc_m": ("non-negative", "under-keel clearance in metres", "1.2"),
    "service_speed_kn": ("positive", "calm-water service speed in knots", "19.5"),
    "speed_range_kn": ("range", "the slowest and fastest engine settings in knots", "[5.0, 19.5]"),
    "displacement_t": ("positive", "displacement in tonnes", "125000.0"),
    "length_m": ("positive", "waterline length in metres", "299.0"),
    "beam_m": ("positive", "waterline breadth in metres", "50.0"),
    "speed_loss": ("choice", f"speed loss in waves, one of {', '.join(SPEED_LOSSES)}", '"stawave1"'),
    "calm_resistance_kn": ("positive", "calm-water resistance at the service speed in kN", "3000.0"),
    "outside_validity": ("validity", "a speed-loss formula outside its range: refuse or warn", '"warn"'),
    "max_wind_ms": ("positive", "the wind the ship never sails in, m/s", "25.0"),
    "max_wave_m": ("positive", "the significant wave height it never sails in, m", "5.0"),
    "danger_wind_ms": ("positive", "wind of the danger zones it avoids while forecast, m/s", "11.0"),
    "danger_wave_m": ("positive", "waves of the danger zones it avoids while forecast, m", "4.0"),
    "ice_curve": (
        "ice_curve",
        "the speed in level ice against its thickness (ice trials or model tests): thickness_m and "
        "speed_kn, two lists",
        "{thickness_m = [0.0, 1.5, 2.1], speed_kn = [19.5, 5.5, 2.0]}",
    ),
    "fuel": (
        "fuel",
        "the fuel curve: a table speeds_kn / rates_t_per_h, or reference_speed_kn "
        "and reference_rate_t_per_h (rate ~ speed^3)",
        "{speeds_kn = [10.0, 12.0], rates_t_per_h = [0.6, 1.0]}",
    ),
    "sources": (
        "sources",
        "where each value comes from ('assumption: ...' when assumed)",
        '{draft_m = "the owner\'s data sheet"}',
    ),
}
REQUIRED = ("name", "service_speed_kn")
#: The vessel files shipped with the package (load(name) reads them).
EXAMPLES = ("arc7-lng-carrier", "arc7-shuttle-tanker", "pc6-general-cargo", "sotnikova-container-ship")


#: The plausible range of each number (min, max) and what it is drawn from: a value outside is a
#: typing error (a beam of 1e30 m), refused naming the range.
RANGES = {
    "draft_m": (0.3, 30.0, "the deepest-draught ship built, Seawise Giant, drew 24.6 m"),
    "ukc_m": (0.0, 10.0, "under-keel clearance is a fraction of the draft (assumption: at most 10 m)"),
    "service_speed_kn": (1.0, 45.0, "fast ferries make about 40 kn; merchant ships 10-25 kn"),
    "displacement_t": (10.0, 700000.0, "Seawise Giant, the largest ship built, displaced 657 019 t"),
    "length_m": (5.0, 500.0, "Seawise Giant, the longest ship built, was 458.5 m long"),
    "beam_m": (1.0, 80.0, "the widest ship afloat, the Prelude FLNG, is 74 m wide"),
    "calm_resistance_kn": (
        1.0,
        20000.0,
        "an Arc7 LNG carrier needs about 3000 kN at 19.5 kn (assumption: 20 000 kN)",
    ),
    "max_wind_ms": (1.0, 80.0, "the strongest sustained winds measured at sea are about 80 m/s"),
    "max_wave_m": (0.5, 30.0, "the highest significant waves measured are about 20 m"),
    "danger_wind_ms": (1.0, 80.0, "as max_wind_ms"),
    "danger_wave_m": (0.5, 30.0, "as max_wave_m"),
    "speed_range_kn": (0.5, 45.0, "as service_speed_kn"),
    "fuel": (0.0, 50.0, "the largest container ships burn about 10 t/h (250 t a day): rates up to 50 t/h"),
}


def _fail(path: str, key: str, message: str) -> NoReturn:
    kind, what, example = FIELDS[key]
    raise VesselFileError(f"vessel file {path}: {key} ({what}) {message}; e.g. {key} = {example}")


def _number(path: str, key: str, value: Any, minimum: float = 0.0, strict: bool = True) -> float:
    try:  # (an integer too large for a float, e.g. 1 followed by 400 zeros, is not finite either)
        ok = isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)
    except OverflowError:
        ok = False
    if not ok or value < minimum or (strict and value == minimum):
        _fail(path, key, f"must be a {'positive' if strict else 'non-negative'} number, got {value!r}")
    if key in RANGES:
        lo, hi, why = RANGES[key]
        if not lo <= value <= hi:
            _fail(path, key, f"must be between {lo:g} and {hi:g} ({why}), got {value!r}")
    return float(value)


def _check(path: str, data: dict[str, Any]) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for key, value in data.items():
        if key not in FIELDS:
            near = difflib.get_close_matches(key, FIELDS, n=1)
            raise VesselFileError(
                f"vessel file {path}: unknown field {key!r}"
                + (f" (did you mean {near[0]}?)" if near else "")
                + f"; the fields are {', '.join(FIELDS)}"
            )
        kind = FIELDS[key][0]
        if kind == "text":
            if not isinstance(value, str) or not value.strip():
                _fail(path, key, f"must be a non-empty text, got {value!r}")
        elif kind == "class":
            try:
                value = get_class(str(value)).name
            except (KeyError, ValueError) as exc:
                _fail(path, key, f"is not an ice class seaway knows ({exc})")
        elif kind in ("positive", "non-negative"):
            value = _number(path, key, value, strict=kind == "positive")
        elif kind == "range":
            if not (isinstance(value, list) and len(value) == 2):
                _fail(path, key, f"must be two speeds [slowest, fastest], got {value!r}")
            value = tuple(_number(path, key, v) for v in value)
            if value[0] > value[1]:
                _fail(path, key, f"must be [slowest, fastest], got {list(value)}")
        elif kind == "validity" and value not in ("refuse", "warn"):
            _fail(path, key, f"must be refuse or warn, got {value!r}")
        elif kind == "choice" and value not in SPEED_LOSSES:
            _fail(path, key, f"must be one of {', '.join(SPEED_LOSSES)}, got {value!r}")
        elif kind == "fuel":
            value = _fuel(path, value, data)
        elif kind == "ice_curve":
            value = _ice_curve(path, value, data)
        elif kind == "sources":
            if not isinstance(value, dict) or any(k not in FIELDS for k in value):
                bad = [k for k in value if k not in FIELDS] if isinstance(value, dict) else value
                _fail(path, key, f"must be a table of the file's fields, got {bad!r}")
        out[key] = value
    for key in REQUIRED:
        if key not in out:
            _fail(path, key, "is missing")
    return out


def _ice_curve(path: str, value: Any, data: dict[str, Any]) -> IceCurve:
    if not (isinstance(value, dict) and set(value) == {"thickness_m", "speed_kn"}):
        _fail(path, "ice_curve", f"must be a table of thickness_m and speed_kn, got {value!r}")
    h, v = value["thickness_m"], value["speed_kn"]
    if not (isinstance(h, list) and isinstance(v, list)):
        _fail(path, "ice_curve", "needs thickness_m and speed_kn, two lists of one length")
    numbers = [_number(path, "ice_curve", x, strict=False) for x in h + v]
    source = (
        str(data.get("sources", {}).get("ice_curve", "")) if isinstance(data.get("sources"), dict) else ""
    )
    try:
        return IceCurve(tuple(numbers[: len(h)]), tuple(numbers[len(h) :]), source)
    except SeawayError as exc:
        _fail(path, "ice_curve", f"is not a usable curve ({exc})")


def _fuel(path: str, value: Any, data: dict[str, Any]) -> tuple[tuple[float, ...], tuple[float, ...]]:
    if not isinstance(value, dict):
        _fail(path, "fuel", f"must be a table, got {value!r}")
    if "speeds_kn" in value or "rates_t_per_h" in value:
        v, q = value.get("speeds_kn"), value.get("rates_t_per_h")
        if not (isinstance(v, list) and isinstance(q, list) and len(v) == len(q) and v):
            _fail(path, "fuel", "needs speeds_kn and rates_t_per_h, two lists of one length")
        return (
            tuple(_number(path, "fuel", x) for x in v),
            tuple(_number(path, "fuel", x, strict=False) for x in q),
        )
    if {"reference_speed_kn", "reference_rate_t_per_h"} <= set(value):
        ref_v = _number(path, "fuel", value["reference_speed_kn"])
        ref_q = _number(path, "fuel", value["reference_rate_t_per_h"])
        lo, hi = data.get("speed_range_kn") or [ref_v, ref_v]
        speeds = [float(lo) + k for k in range(int(math.floor(float(hi) - float(lo))) + 1)]
        if speeds[-1] < float(hi):
            speeds.append(float(hi))
        return tuple(speeds), tuple(ref_q * (s / ref_v) ** 3 for s in speeds)
    _fail(
        path,
        "fuel",
        f"has neither speeds_kn/rates_t_per_h nor reference_speed_kn/"
        f"reference_rate_t_per_h (it has {sorted(value)})",
    )


def _read(path: str) -> dict[str, Any]:
    try:
        with open(path, "rb") as f:
            raw = f.read()
    except OSError as exc:
        raise VesselFileError(f"vessel file {path}: cannot read it ({exc.strerror})") from None
    try:
        if path.lower().endswith(".json"):
            data = json.loads(raw.decode("utf-8"))
        else:
            data = tomllib.loads(raw.decode("utf-8"))
    except (ValueError, UnicodeDecodeError) as exc:  # TOMLDecodeError and JSONDecodeError
        fmt = "JSON" if path.lower().endswith(".json") else "TOML"
        raise VesselFileError(
            f"vessel file {path}: not valid {fmt} ({exc}); see seaway.vessel.profile for the format"
        ) from None
    if not isinstance(data, dict):
        raise VesselFileError(f"vessel file {path}: must hold a table of fields, not {type(data).__name__}")
    return data


def example_path(name: str) -> str:
    """The path of a vessel file shipped with the package (EXAMPLES)."""
    return str(resources.files("seaway.vessel") / "examples" / f"{name}.toml")


def load(path: str | os.PathLike[str]) -> Vessel:
    """A vessel file (TOML, or JSON by its .json extension) as a Vessel, every field checked; a
    name of EXAMPLES reads the shipped example. VesselFileError names the field and the fix."""
    path = os.fspath(path)
    shown = path
    if not os.path.exists(path) and path in EXAMPLES:
        path, shown = example_path(path), f"{path} (shipped with seaway)"
    elif not os.path.exists(path):
        raise VesselFileError(
            f"vessel file {path}: no such file (the examples shipped with seaway: {', '.join(EXAMPLES)})"
        )
    d = _check(path, _read(path))
    same = (
        "max_wind_ms",
        "max_wave_m",
        "danger_wind_ms",
        "danger_wave_m",
        "beam_m",
        "length_m",
        "calm_resistance_kn",
        "displacement_t",
        "speed_loss",
        "outside_validity",
        "name",
        "ice_class",
        "draft_m",
        "ukc_m",
        "speed_range_kn",
        "ice_curve",
    )
    if d.get("speed_loss") == "stawave1" and not all(
        k in d for k in ("beam_m", "length_m", "calm_resistance_kn")
    ):
        _fail(path, "speed_loss", "= 'stawave1' needs beam_m, length_m and calm_resistance_kn")
    speeds, rates = d.get("fuel", ((), ()))
    return Vessel(
        speed_kn=d["service_speed_kn"],
        fuel_speeds_kn=speeds,
        fuel_rates_t_per_h=rates,
        sources=dict(d.get("sources", {})),
        path=shown,
        **{k: d[k] for k in same if k in d},
    )
