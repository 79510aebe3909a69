"""Query-time constraints: via-points (an ordered list of waypoints, each leg optimal) and the
turn penalty (the expanded-state search of cpp/seaway/turns.hpp). Used by PreparedChart.route."""

from __future__ import annotations

import math

import numpy as np

from . import _core


def turn_table(turn_penalty) -> tuple[list[float], list[float]] | None:
    """(angles in degrees, costs) of a turn penalty given as a cost per degree of course change
    (a number) or a table {angle_deg: cost} / [(angle_deg, cost), ...], linear between its
    points and flat beyond them; None for no penalty."""
    if turn_penalty is None:
        return None
    if isinstance(turn_penalty, bool):
        raise TypeError("turn_penalty must be a cost per degree or a table {angle_deg: cost}, got a bool")
    if isinstance(turn_penalty, (int, float, np.integer, np.floating)):
        p = float(turn_penalty)
        if not (math.isfinite(p) and p >= 0):
            raise ValueError(f"turn_penalty per degree must be finite and >= 0, got {turn_penalty!r}")
        return [0.0, 180.0], [0.0, 180.0 * p]
    items = turn_penalty.items() if isinstance(turn_penalty, dict) else turn_penalty
    try:
        pairs = sorted((float(a), float(c)) for a, c in items)
    except (TypeError, ValueError):
        raise TypeError("turn_penalty must be a cost per degree or a table {angle_deg: cost} "
                        f"(e.g. {{0: 0, 45: 2, 90: 10, 180: 40}}), got {turn_penalty!r}") from None
    if not pairs:
        raise ValueError("turn_penalty table is empty; give e.g. {0: 0, 90: 10, 180: 40}")
    angles, costs = [a for a, _ in pairs], [c for _, c in pairs]
    if len(set(angles)) != len(angles):
        raise ValueError(f"turn_penalty table repeats an angle: {angles}")
    if angles[0] < 0 or angles[-1] > 180:
        raise ValueError(f"turn_penalty angles must lie in 0..180 degrees, got {angles}")
    if not all(math.isfinite(c) and c >= 0 for c in costs):
        raise ValueError(f"turn_penalty costs must be finite and >= 0, got {costs}")
    if angles[0] > 0:
        angles, costs = [0.0] + angles, [costs[0]] + costs
    if angles[-1] < 180:
        angles, costs = angles + [180.0], costs + [costs[-1]]
    return angles, costs


def incoming_offset(prepared, pixels: np.ndarray) -> int:
    """The stencil index of a path's last step (for the next leg's first turn), or -1."""
    if len(pixels) < 2:
        return -1
    di, dj = (int(v) for v in pixels[-1] - pixels[-2])
    cols = prepared.chart.shape[1]
    if prepared.chart.grid.wrap:
        dj = (dj + cols // 2) % cols - cols // 2
    return _core.offset_index(prepared._router, di, dj)


def search_leg(prepared, s, e, weight, turns, incoming):
    """(cost, flat path, stats, cumulative) of one leg between located pixels."""
    from ._interrupt import interruptible

    if turns is None:
        return prepared._search(s, e, weight)
    angles, costs = turns
    return interruptible(lambda cancel: _core.route_turns(
        prepared._router, prepared._flat(s), prepared._flat(e), weight, angles, costs, incoming,
        cancel))
