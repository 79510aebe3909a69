"""The ship a voyage is planned for: one Vessel drives every kind of route (an ice chart, a season
of charts, a forecast, ice and weather together). It carries the ice class, the service speed,
draft and under-keel clearance, the speed in level ice against its thickness (IceCurve), the
speed-loss formula and weather limits, and the fuel curve; a vessel file (seaway.vessel.load)
gives each value its source. seaway.vessel re-exports both."""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
import numpy.typing as npt

from .. import native as _core
from ..base.validate import number
from ..errors import SeawayError

#: The speed-loss formulas of the engine (cpp/seaway/weather.hpp).
SPEED_LOSSES: tuple[str, ...] = tuple(_core.SpeedLoss.__members__)


@dataclass(frozen=True)
class IceCurve:
    """A ship's speed in level ice against the ice's thickness (an h-v curve, as ice model tests
    and ice trials give it): `thickness_m` increasing from 0, `speed_kn` at each; linear between
    the points, no speed of its own in thicker ice than the last point (an icebreaker's escort).
    `source`: where the points come from."""

    thickness_m: tuple[float, ...]
    speed_kn: tuple[float, ...]
    source: str = ""

    def __post_init__(self) -> None:
        h, v = np.asarray(self.thickness_m, float), np.asarray(self.speed_kn, float)
        if h.ndim != 1 or h.shape != v.shape or h.size < 2:
            raise SeawayError(
                "an ice curve needs thickness_m and speed_kn, two lists of one length (at least 2 points), "
                "e.g. thickness_m = [0.0, 1.0, 1.5], speed_kn = [14.0, 8.0, 4.0]"
            )
        if not (np.all(np.isfinite(h)) and np.all(np.isfinite(v)) and h[0] >= 0 and np.all(np.diff(h) > 0)):
            raise SeawayError(f"an ice curve's thickness_m must increase from 0 m, got {list(h)}")
        if np.any(v < 0) or np.any(np.diff(v) > 0):
            raise SeawayError(f"an ice curve's speed_kn must not grow with the thickness, got {list(v)}")
        if h[-1] > 10 or v[0] > 60:
            raise SeawayError(
                f"an ice curve of {h[-1]:g} m and {v[0]:g} kn is not a ship's: level ice is at most a few "
                "metres thick (WMO-No. 259), ships make at most about 40 kn"
            )

    def speed(self, thickness_m: npt.ArrayLike, v0_kn: float) -> npt.NDArray[np.float64]:
        """The speed (kn) in level ice of `thickness_m` (m), at most `v0_kn` (the open-water speed
        the voyage asks for); 0 beyond the curve's last point."""
        h = np.asarray(thickness_m, float)
        pts_h = np.asarray(self.thickness_m, float)
        pts_v = np.asarray(self.speed_kn, float)
        if pts_h[0] > 0:  # from open water (0 m, V0) to the first point
            pts_h, pts_v = np.r_[0.0, pts_h], np.r_[max(v0_kn, pts_v[0]), pts_v]
        v = np.interp(np.nan_to_num(h, nan=np.inf), pts_h, pts_v, right=0.0)
        v = np.where(h > pts_h[-1], 0.0, v)
        return np.minimum(v, float(v0_kn))

    def describe(self) -> str:
        pts = ", ".join(f"{h:g} m {v:g} kn" for h, v in zip(self.thickness_m, self.speed_kn))
        return f"the ship's ice curve ({pts})"


@dataclass(frozen=True)
class Vessel:
    """A ship. Speeds in knots, displacement in tonnes, lengths in metres, limits in SI.

    speed_kn: the calm-water service speed (V0 in ice, the weather routes' speed).
    ice_class: the class (seaway.ice.classes: Arc4 ... Arc9, PC1 ... PC7, IA Super, ...) or None.
    draft_m, ukc_m: draft and under-keel clearance (ukc None: 10 % of the draft).
    ice_curve: the speed in level ice (IceCurve), or None for the class's default model
        (Andreeva 2021 for Register classes, the IMO POLARIS limits for Polar Classes).
    speed_loss, displacement_t, beam_m, length_m, calm_resistance_kn: speed lost in waves
        (Khokhlov, STAWAVE-1); max_wind_ms, max_wave_m: never crossed; danger_*: avoided.
    fuel_speeds_kn, fuel_rates_t_per_h: the fuel curve (t/h at each engine setting).
    name, sources, path: what the ship is, where each value comes from, the file it was read from."""

    speed_kn: float = 15.0
    displacement_t: float = 15000.0
    #: "khokhlov" (Olovyannikov 2025; 5000-25000 t, 9-20 kn), "stawave1" (any size: STAWAVE-1's added
    #: resistance in bow waves at constant power; needs beam_m, length_m, calm_resistance_kn),
    #: or "none" (waves only limit where the ship may go).
    speed_loss: str = "khokhlov"
    max_wind_ms: float = 25.0
    max_wave_m: float = 5.0
    danger_wind_ms: float | None = None  # Sotnikova 2009: 11 m/s zones avoided while forecast
    danger_wave_m: float | None = None  # danger zones by significant wave height, avoided too
    outside_validity: str = "refuse"  # a speed-loss model outside its range: or "warn"
    beam_m: float | None = None  # waterline breadth
    length_m: float | None = None  # waterline length
    calm_resistance_kn: float | None = None  # calm-water resistance at speed_kn, kN
    name: str = ""
    ice_class: str | None = None
    draft_m: float | None = None
    ukc_m: float | None = None
    speed_range_kn: tuple[float, float] | None = None
    ice_curve: IceCurve | None = None
    fuel_speeds_kn: tuple[float, ...] = ()
    fuel_rates_t_per_h: tuple[float, ...] = ()
    sources: dict[str, str] = field(default_factory=dict, compare=False)
    path: str = ""

    @classmethod
    def of_class(cls, ice_class: str, speed_kn: float = 12.0, **fields: Any) -> Vessel:
        """A ship known only by its ice class (``--vessel CLASS``), at `speed_kn` in open water."""
        return cls(speed_kn=speed_kn, ice_class=ice_class, name=f"{ice_class} ship", **fields)

    def with_speed(self, speed_kn: float | None) -> Vessel:
        """The same ship at another service speed (None: as it is)."""
        return self if speed_kn is None else replace(self, speed_kn=float(speed_kn))

    @property
    def vessel(self) -> Vessel:
        """The ship itself (what a vessel file's profile called its weather vessel)."""
        return self

    @property
    def assumed(self) -> tuple[str, ...]:
        """The fields whose source says they are assumptions."""
        return tuple(k for k, v in self.sources.items() if str(v).lower().startswith("assumption"))

    def describe(self) -> str:
        """One line for the outputs: name, class, speed and where it was read from."""
        cls = f", {self.ice_class}" if self.ice_class else ""
        where = f" (vessel file {self.path})" if self.path else ""
        return f"{self.name or 'ship'}{cls}, {self.speed_kn:g} kn{where}"

    def _outside(self, msg: str) -> None:
        if self.outside_validity == "warn":
            warnings.warn(msg, stacklevel=4)
        else:
            raise SeawayError(
                msg + "; pass outside_validity='warn' to go on (in a vessel file: "
                'outside_validity = "warn"), or another speed_loss'
            )

    def check_waves(self, max_hs_m: float) -> None:
        """STAWAVE-1 holds for Hs <= 2.25 sqrt(L / 100) (ITTC 7.5-04-01-01.1)."""
        if self.speed_loss != "stawave1" or self.length_m is None:
            return
        limit = 2.25 * np.sqrt(self.length_m / 100)
        if max_hs_m > limit:
            self._outside(
                f"STAWAVE-1 holds for significant heights up to 2.25 sqrt(L/100) = "
                f"{limit:.2f} m; the forecast has {max_hs_m:.2f} m"
            )

    def check(self, waves: bool = True) -> None:
        """Validate the numbers; `waves`: whether the forecast has waves (else the speed-loss
        formula's range is not checked: it is not used)."""
        number(self.speed_kn, "speed_kn", above=0, what="positive", example=12.0)
        for name in ("displacement_t", "max_wind_ms", "max_wave_m"):
            number(getattr(self, name), name, above=0)
        for name in ("danger_wind_ms", "beam_m", "length_m", "calm_resistance_kn"):
            if getattr(self, name) is not None:
                number(getattr(self, name), name, above=0)
        if self.speed_loss not in SPEED_LOSSES:
            raise SeawayError(f"speed_loss must be one of {SPEED_LOSSES}, got {self.speed_loss!r}")
        if self.speed_loss == "stawave1":
            sizes = (self.beam_m, self.length_m, self.calm_resistance_kn)
            if not all(v is not None and np.isfinite(v) and v > 0 for v in sizes):
                raise SeawayError(
                    "speed_loss='stawave1' needs positive beam_m, length_m and "
                    "calm_resistance_kn (kN at speed_kn)"
                )
        if self.speed_loss == "khokhlov" and waves:
            inside = 5000 <= self.displacement_t <= 25000 and 9 <= self.speed_kn <= 20
            if not inside:
                self._outside(
                    f"Khokhlov's speed-loss formula holds for 5000-25000 t and 9-20 kn; "
                    f"this vessel is {self.displacement_t:g} t at {self.speed_kn:g} kn "
                    "(speed_loss='stawave1' covers other ships)"
                )

    def to_core(self, max_wind_ms: float | None = None, danger: bool = True) -> _core.Vessel:
        """The engine's typed vessel, with the wind and wave limits lowered to danger_wind_ms
        and danger_wave_m if set (danger=False: the hard limits only)."""
        max_wave_m = self.max_wave_m
        if danger and self.danger_wave_m is not None:
            max_wave_m = min(max_wave_m, self.danger_wave_m)
        if max_wind_ms is None:
            max_wind_ms = (
                self.max_wind_ms
                if self.danger_wind_ms is None or not danger
                else min(self.max_wind_ms, self.danger_wind_ms)
            )
        v = _core.Vessel()
        v.speed_kn, v.displacement_t = self.speed_kn, self.displacement_t
        v.speed_loss = getattr(_core.SpeedLoss, self.speed_loss)
        v.max_wind_ms, v.max_wave_m = max_wind_ms, max_wave_m
        v.beam_m, v.length_m = self.beam_m or 0.0, self.length_m or 0.0
        v.calm_resistance_kn = self.calm_resistance_kn or 0.0
        return v
