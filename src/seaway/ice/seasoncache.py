"""The hours per km a season's charts give a class, kept between routes (SeasonGrid.class_frames).

A batch of voyages (seaway.fleet.route_voyages) routes the same class through the same charts
from many departures and ends; the speed model over every chart of the season is the larger
part of one route's time, and the same for each of them. `FrameCache` keeps the `Frames` it
computed (read-only, so no route changes another's), the most recently used first, up to
`limit_bytes` in all; frames larger than the limit alone are not kept. Thread-safe (a batch
routes on threads); pickled empty (a Dask worker builds its own)."""

from __future__ import annotations

import threading
from collections import OrderedDict
from collections.abc import Callable, Hashable
from typing import Any

import numpy as np
import numpy.typing as npt

#: What the cache may hold by default: 2 GiB (three classes of a 120-day season of 1.5 M pixels).
LIMIT_BYTES = 2 * 2**30


class Frames:
    """A class's hours per km in every chart of a season (frames, rows, cols; inf where closed;
    read-only), with what each departure's model needs of them: `open_from[k]` (pixels some
    chart from k on opens), `closed_for[k]` (how many charts from k on each pixel stays closed,
    int16, at most 32767: the engine skips them, cpp/seaway/ice_time.hpp), and the least and
    largest finite hours per km of each chart (7 bytes per pixel and chart in all)."""

    def __init__(self, hours: npt.NDArray[np.float32]) -> None:
        hours.flags.writeable = False
        self.hours = hours
        n = hours.shape[0]
        self.open_from = np.empty(hours.shape, bool)
        self.closed_for = np.empty(hours.shape, np.int16)
        self.frame_min = np.full(n, np.inf)
        self.frame_max = np.zeros(n)
        later = np.zeros(hours.shape[1:], bool)
        opens = np.full(hours.shape[1:], n, np.int64)  # the first chart from k on that opens it
        for k in range(n - 1, -1, -1):  # frame by frame: no stack-sized temporaries
            finite = np.isfinite(hours[k])
            later = later | finite
            self.open_from[k] = later
            opens = np.where(finite, k, opens)
            self.closed_for[k] = np.minimum(opens - k, np.iinfo(np.int16).max)
            if finite.any():
                self.frame_min[k] = float(hours[k][finite].min())
                self.frame_max[k] = float(hours[k][finite].max())
        self.open_from.flags.writeable = self.closed_for.flags.writeable = False

    @property
    def nbytes(self) -> int:
        return self.hours.nbytes + self.open_from.nbytes + self.closed_for.nbytes


class FrameCache:
    """Frames by key (class, speed, speed model, options)."""

    def __init__(self, limit_bytes: int = LIMIT_BYTES) -> None:
        self.limit_bytes = int(limit_bytes)
        self._frames: OrderedDict[Hashable, tuple[Any, Frames]] = OrderedDict()
        self._lock = threading.Lock()

    def get(self, key: Hashable | None, keep: Any, compute: Callable[[], npt.NDArray[np.float32]]) -> Frames:
        """The frames for `key`, computed once (key None: not cached). `keep`: an object the key
        names by id (a speed table or curve), held so that its id is not reused."""
        if key is None:
            return Frames(compute())
        with self._lock:  # one thread computes a stack; the others wait for it
            if key in self._frames:
                self._frames.move_to_end(key)
                return self._frames[key][1]
            frames = Frames(compute())
            if frames.nbytes <= self.limit_bytes:
                self._frames[key] = (keep, frames)
                while self.nbytes > self.limit_bytes:
                    self._frames.popitem(last=False)
            return frames

    @property
    def nbytes(self) -> int:
        """The bytes the cache holds."""
        return sum(f.nbytes for _, f in self._frames.values())

    def __getstate__(self) -> dict:
        return {"limit_bytes": self.limit_bytes}

    def __setstate__(self, state: dict) -> None:
        self.__init__(state["limit_bytes"])  # type: ignore[misc]


def speed_key(ice_class: Any, v0_kn: float, speed: Any, options: dict) -> Hashable | None:
    """The cache key of a class's stack, or None when an option cannot be told apart by value
    (the stack is then computed for that route alone). Tables and curves are named by id."""
    name = getattr(ice_class, "name", ice_class)
    how = speed if isinstance(speed, str) else ("id", id(speed))
    try:
        opts = tuple(sorted(options.items()))
        hash(opts)
    except TypeError:
        return None
    return (str(name), float(v0_kn), how, opts)
