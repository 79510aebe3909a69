"""The time of a voyage across an ice chart (OpenChart.route): the ship's speed in each pixel's
ice (seaway.ice.speed: its ice curve, else Andreeva 2021 or IMO POLARIS by its class), where it
has none of its own the icebreaker's escort (when allowed) or the ice closed to the search, and
the hours per km the quickest route is searched on. The route that is searched and the time it
is given never disagree: ice the ship cannot cross on its own is avoided, or escorted and
marked."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..base.units import KM_PER_NM
from ..errors import ChartError, SeawayError
from ..ice.andreeva import DEFAULT_STAGE_THICKNESS
from ..ice.classes import get_class
from ..ice.speed import ice_speed, thickness

#: The speed under icebreaker escort when none is given: an assumption (NSR escorts in heavy
#: first-year ice make a few knots; seaway.voyage.timing, docs/user/voyage-time.md).
DEFAULT_ESCORT_KN = 6.0
#: A chart this many days older than a leg that uses it is said to be old.
CHART_AGE_DAYS = 3.0


@dataclass
class IceTime:
    """knots: the speed on the chart's grid (a DataArray; the escort's where escorted, 0 where
    the ship may not go); own: its own speed; escorted: where the escort's speed is used;
    closed: where ice the search would allow is closed because the ship has no speed there (and
    no escort); model: the speed model in words; escort_kn: the escort's speed or None."""

    knots: object
    own: np.ndarray
    escorted: np.ndarray
    closed: np.ndarray
    model: str
    escort_kn: float | None
    #: The ice's thickness (m) the speed was read at, and the most the ship passes on its own.
    thickness_m: np.ndarray | None = None
    limit: str = ""

    def why(self, rc) -> str:
        """Why the ship has no speed of its own at pixel rc, in words."""
        h = "" if self.thickness_m is None else f"{float(self.thickness_m[rc]):.2f} m of ice"
        return f"the ship has no speed of its own in {h or 'this ice'}{self.limit} (--escort: under escort)"

    def hours_per_km(self) -> np.ndarray:
        """Hours per km at each pixel (inf where the ship has no speed): the cost of the
        quickest route."""
        v = np.asarray(self.knots.values, float) * KM_PER_NM
        with np.errstate(divide="ignore"):
            return np.where(v > 0, 1.0 / np.where(v > 0, v, 1.0), np.inf)


def ice_time(
    chart, ice_class, ship, cost, *, escort=False, escort_kn=None, stage_thickness=None, draft_m=None
):
    """The IceTime of `ship` (a Vessel: speed_kn the open-water speed, its ice_curve) on the
    opened ice `chart`, for the search's `cost` (finite where the class may go)."""
    rule = DEFAULT_STAGE_THICKNESS if stage_thickness is None else stage_thickness
    knots = ice_speed(
        chart.layers,
        ice_class,
        ship.speed_kn,
        curve=ship.ice_curve,
        fast_ice=chart.options.fast_ice,
        stage_thickness=rule,
        depth=chart.depth if draft_m is not None else None,
        draft=draft_m,
    )
    own = np.asarray(knots.values, float)
    passable = np.isfinite(np.asarray(cost.values if hasattr(cost, "values") else cost, float))
    if chart.land is not None:
        passable &= ~np.asarray(chart.land.values, bool)
    if own.shape != passable.shape:  # a projected chart's speed on its native grid: transposed?
        raise ChartError(f"the speed in ice has shape {own.shape}, the chart {passable.shape}")
    stuck = passable & ~(own > 0)
    model = str(knots.attrs["model"])
    h, _ = thickness(chart.layers, chart.options.fast_ice, rule)
    cls = get_class(ice_class)
    if ship.ice_curve is not None:
        limit = f"; its ice curve ends at {ship.ice_curve.thickness_m[-1]:g} m (x C/10)"
    elif cls.system in ("IACS", "FSICR"):
        limit = f"; IMO POLARIS: special consideration for {cls.name}"
    else:
        limit = f"; {cls.name} passes {cls.h_pass:g} m (Andreeva 2021's f2 = 0)"
    if escort:
        kn = float(DEFAULT_ESCORT_KN if escort_kn is None else escort_kn)
        if not (np.isfinite(kn) and kn > 0):
            raise SeawayError(f"the escort speed must be a positive number of knots, got {escort_kn!r}")
        # the escort wherever the ship alone is slower: thicker ice is never quicker than thinner
        escorted = passable & (own < kn)
        speed = np.where(escorted, kn, own)
        source = "given" if escort_kn is not None else "an assumption, the default"
        model += f"; under icebreaker escort {kn:g} kn ({source}) where the ship alone is slower"
        return IceTime(knots.copy(data=speed), own, escorted, np.zeros_like(stuck), model, kn, h, limit)
    return IceTime(knots, own, np.zeros_like(stuck), stuck, model, None, h, limit)


def chart_age(chart_date: str, departure, hours: float) -> list[str]:
    """Sentences on the chart's age against the departure and the arrival (`hours` later): its
    date always, a warning when it is more than CHART_AGE_DAYS older than the last leg."""
    if not chart_date or departure is None:
        return []
    try:
        date = np.datetime64(chart_date.replace(" ", "T"), "m")
    except ValueError:
        return []
    dep = np.datetime64(departure, "m")
    arrival = dep + np.timedelta64(int(round(hours * 60)), "m") if np.isfinite(hours) else dep
    days = float((arrival - date) / np.timedelta64(1, "D"))
    lead = float((dep - date) / np.timedelta64(1, "D"))
    out = [f"ice chart of {chart_date}: {lead:+.1f} days at departure, {days:+.1f} days at arrival"]
    if days > CHART_AGE_DAYS:
        out.append(
            f"warning: the ice chart of {chart_date} is {days:.1f} days older than the voyage's last leg "
            f"(more than {CHART_AGE_DAYS:g}): the ice may have changed; use a newer chart or a season of charts"
        )
    elif lead < -CHART_AGE_DAYS:
        out.append(
            f"warning: the ice chart of {chart_date} is {-lead:.1f} days after the departure: it shows ice "
            "the ship will not meet at the start"
        )
    return out


def search_cost(cost, timing, objective):
    """What the search prices: the impact where the ship can go (its own speed, or escorted),
    or its hours per km; inf where it cannot."""
    values = np.asarray(cost.values, float)
    open_ = np.isfinite(values) & ~timing.closed
    if objective == "time":
        return cost.copy(data=np.where(open_, timing.hours_per_km(), np.inf))
    return cost.copy(data=np.where(open_, values, np.inf))


def time_notes(timing, objective, edge_cost) -> list[str]:
    found = (
        "the quickest route (objective time: the line integral of hours per km)"
        if objective == "time"
        else f"the route of least ice impact (Grinyak et al. 2022, edge cost {edge_cost})"
    )
    out = [f"{found}, timed by the ship's speed in the ice: {timing.model}"]
    if timing.closed.any():
        out.append(
            f"ice the class may enter but the ship has no speed of its own in is avoided "
            f"({int(timing.closed.sum())} pixels); escort=True (--escort) takes it under icebreaker escort"
        )
    return out


def end_reasons(shallow, timing, over=None):
    """(row, col) -> extra reasons an end is impassable: too shallow, no speed of its own, over
    the class's concentration limit (`over`: over_limit)."""
    if shallow is None and over is None and (timing is None or not timing.closed.any()):
        return None

    def why(rc):
        out = list(shallow(rc)) if shallow is not None else []
        if timing is not None and timing.closed[rc]:
            out.append(timing.why(rc))
        if over is not None and over(rc):
            out.append(over(rc))
        return out

    return why


def blocked_words(shallow, timing) -> str | None:
    if shallow is not None:
        return "water shallower than draft + UKC"
    if timing is not None and timing.closed.any():
        return "ice the ship has no speed of its own in (--escort takes it under icebreaker escort)"
    return None


def total_concentration(chart):
    """The chart's total concentration in tenths (its CT or sea_ice_concentration layer), or None."""
    layers = chart.layers
    name = next((n for n in ("CT", "sea_ice_concentration") if layers is not None and n in layers), None)
    return None if name is None else np.asarray(layers[name].values, float)


def over_limit(chart, ice_class):
    """(row, col) -> why the concentration limit closes the pixel (concentration_closed), or ""
    where it does not."""
    ct = total_concentration(chart)
    if ct is None:
        return lambda rc: ""
    limit = get_class(ice_class).max_concentration

    def why(rc):
        if not ct[rc] > limit:
            return ""
        return (
            f"total concentration {ct[rc]:g}/10, over {ice_class}'s limit for independent "
            f"navigation ({limit:g}/10; concentration_limit)"
        )

    return why


def concentration_closed(chart, ice_class, cost):
    """`cost` with ice over the class's concentration limit for independent navigation closed
    (inf where the total concentration exceeds its max_concentration, Grinyak et al. 2022 Table
    1; seaway.ice.classes), as a season closes it by default (concentration_limit)."""
    ct = total_concentration(chart)
    if ct is None:
        raise ChartError(
            f"{chart.source} gives no total concentration (CT or sea_ice_concentration): the "
            "concentration limit cannot be read; give concentration_limit=False"
        )
    with np.errstate(invalid="ignore"):
        over = ct > get_class(ice_class).max_concentration
    return cost.copy(data=np.where(over, np.inf, np.asarray(cost.values, float)))
