"""The ship of a voyage: a seaway.vessel.Vessel (from a vessel file, or made here from an ice
class), with what it assumes said once."""

from __future__ import annotations

import dataclasses

from ..errors import SeawayError
from ..ice.classes import get_class
from ..vessel import Vessel

#: The open-water speed of a ship known only by its class (said whenever it is used).
DEFAULT_SPEED_KN = 12.0


def as_vessel(vessel: Vessel | str | None, speed_kn: float | None = None, **changes) -> Vessel | None:
    """The voyage's Vessel: `vessel` as it is, or a ship of that ice class at DEFAULT_SPEED_KN
    (the speed recorded as an assumption in its sources), at `speed_kn` when given; `changes`
    (draft_m, ukc_m, displacement_t, ...) replace its values where not None. None stays None
    unless a speed or a change is given (then a ship of no class)."""
    changes = {k: v for k, v in changes.items() if v is not None}
    if isinstance(vessel, str):
        try:
            cls = get_class(vessel).name
        except (KeyError, ValueError) as exc:
            raise SeawayError(str(exc).strip("'\"")) from None
        vessel = Vessel.of_class(
            cls,
            DEFAULT_SPEED_KN,
            sources={
                "speed_kn": f"assumption: {DEFAULT_SPEED_KN:g} kn in open water, the default for a ship known by its class"
            },
        )
    elif vessel is None and (speed_kn is not None or changes):
        vessel = Vessel(speed_kn=DEFAULT_SPEED_KN, name="ship")
    elif vessel is not None and not isinstance(vessel, Vessel):
        raise SeawayError(
            f"vessel must be a seaway.vessel.Vessel, a vessel file's or an ice class, got {vessel!r}"
        )
    if vessel is None:
        return None
    if speed_kn is not None:
        sources = {k: v for k, v in vessel.sources.items() if k != "speed_kn"}
        vessel = dataclasses.replace(vessel, speed_kn=float(speed_kn), sources=sources)
    return dataclasses.replace(vessel, **changes) if changes else vessel


def vessel_notes(vessel: Vessel | None) -> list[str]:
    """What the voyage says of its ship: who it is, and each value assumed for it."""
    if vessel is None:
        return []
    out = [f"vessel: {vessel.describe()}"]
    if (
        "speed_kn" in vessel.sources
        and vessel.sources["speed_kn"].startswith("assumption")
        and not vessel.path
    ):
        out.append(f"{vessel.sources['speed_kn']} (give --speed or --vessel-file)")
    return out
