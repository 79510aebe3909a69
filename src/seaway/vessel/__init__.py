"""The ship a voyage is planned for (seaway.vessel.ship): one Vessel, with its ice class, service
speed, draft, ice curve, weather limits and fuel curve, drives every kind of route; vessel files
(TOML or JSON; the format: seaway.vessel.profile, FIELDS and RANGES) are read by load()."""

from __future__ import annotations

from ..errors import VesselFileError as VesselFileError  # importable here too
from . import profile
from .profile import EXAMPLES, load
from .ship import SPEED_LOSSES, IceCurve, Vessel

#: What load() returned before a vessel file and a Vessel were one (the same class now).
Profile = Vessel

__all__ = ["EXAMPLES", "SPEED_LOSSES", "IceCurve", "Vessel", "load"]

__doc__ = f"{__doc__}\n\n**The vessel-file format** (seaway.vessel.profile). {profile.__doc__}"
