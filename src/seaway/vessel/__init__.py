"""The ship a route is planned for: the weather models' Vessel (speed, speed-loss formula and
weather limits; seaway.vessel.ship) and vessel files (seaway.vessel.profile: load)."""

from __future__ import annotations

from ..errors import VesselFileError as VesselFileError  # importable here too
from .profile import EXAMPLES, Profile, load
from .ship import SPEED_LOSSES, Vessel

__all__ = ["EXAMPLES", "SPEED_LOSSES", "Profile", "Vessel", "load"]  # VesselFileError: seaway.errors
