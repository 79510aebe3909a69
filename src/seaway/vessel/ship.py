"""The ship a weather route is planned for: speed, speed-loss formula and weather limits
(seaway.vessel re-exports it)."""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from .. import _core
from ..base.validate import number

#: The speed-loss formulas of the engine (cpp/seaway/weather.hpp).
SPEED_LOSSES: tuple[str, ...] = tuple(_core.SpeedLoss.__members__)


@dataclass(frozen=True)
class Vessel:
    """A ship for weather routing. Speeds in knots, displacement in tonnes, limits in SI."""

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

    def _outside(self, msg: str) -> None:
        if self.outside_validity == "warn":
            warnings.warn(msg, stacklevel=4)
        else:
            raise ValueError(
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
            raise ValueError(f"speed_loss must be one of {SPEED_LOSSES}, got {self.speed_loss!r}")
        if self.speed_loss == "stawave1":
            sizes = (self.beam_m, self.length_m, self.calm_resistance_kn)
            if not all(v is not None and np.isfinite(v) and v > 0 for v in sizes):
                raise ValueError(
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
