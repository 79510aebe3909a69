"""Type stubs for seaway's private C++ module (see cpp/register_*.cpp)."""

from typing import ClassVar

import numpy as np
import numpy.typing as npt

class Geometry:
    rows: int
    cols: int
    geographic: bool
    dx: float
    dy: float
    lat0: float
    dlat: float
    lon0: float
    dlon: float
    wrap: bool
    def __init__(self) -> None: ...

class CancelToken:
    def __init__(self) -> None: ...
    def set(self) -> None: ...
    @property
    def is_set(self) -> bool: ...
    @property
    def settled(self) -> int: ...

class SearchCancelled(KeyboardInterrupt): ...

class SearchStats:
    @property
    def settled(self) -> int: ...
    @property
    def heap_peak(self) -> int: ...
    @property
    def state_bytes(self) -> int: ...
    @property
    def min_cost(self) -> float: ...

class StepValues:
    @property
    def setting(self) -> npt.NDArray[np.float64] | None: ...
    @property
    def hours(self) -> npt.NDArray[np.float64] | None: ...
    @property
    def fuel_t(self) -> npt.NDArray[np.float64] | None: ...
    @property
    def depart_h(self) -> npt.NDArray[np.float64] | None: ...
    @property
    def wait_h(self) -> npt.NDArray[np.float64] | None: ...

class QueryResult:
    @property
    def cost(self) -> float: ...
    @property
    def path(self) -> npt.NDArray[np.int64]: ...
    @property
    def cumulative(self) -> npt.NDArray[np.float64]: ...
    @property
    def stats(self) -> SearchStats: ...
    @property
    def steps(self) -> StepValues: ...

class MaxCost:
    #: The model's Capabilities (cpp/seaway/capabilities.hpp): static, symmetric, turn_penalty,
    #: time_dependent, smoothable.
    capabilities: ClassVar[dict[str, bool]]
    def __init__(self, cost: npt.NDArray[np.float32] | npt.NDArray[np.float64]) -> None: ...

class MeanCost:
    #: The model's Capabilities (cpp/seaway/capabilities.hpp): static, symmetric, turn_penalty,
    #: time_dependent, smoothable.
    capabilities: ClassVar[dict[str, bool]]
    def __init__(self, cost: npt.NDArray[np.float32] | npt.NDArray[np.float64]) -> None: ...

class IntegralCost:
    #: The model's Capabilities (cpp/seaway/capabilities.hpp): static, symmetric, turn_penalty,
    #: time_dependent, smoothable.
    capabilities: ClassVar[dict[str, bool]]
    def __init__(self, cost: npt.NDArray[np.float32] | npt.NDArray[np.float64]) -> None: ...

class LengthCost:
    #: The model's Capabilities (cpp/seaway/capabilities.hpp): static, symmetric, turn_penalty,
    #: time_dependent, smoothable.
    capabilities: ClassVar[dict[str, bool]]
    def __init__(self, cost: npt.NDArray[np.float32] | npt.NDArray[np.float64]) -> None: ...

class EnteredPixelCost:
    #: The model's Capabilities (cpp/seaway/capabilities.hpp): static, symmetric, turn_penalty,
    #: time_dependent, smoothable.
    capabilities: ClassVar[dict[str, bool]]
    def __init__(self, cost: npt.NDArray[np.float32] | npt.NDArray[np.float64]) -> None: ...

class SpeedLoss:
    none: SpeedLoss
    khokhlov: SpeedLoss
    stawave1: SpeedLoss
    __members__: dict[str, SpeedLoss]

class Vessel:
    speed_kn: float
    displacement_t: float
    speed_loss: SpeedLoss
    beam_m: float
    length_m: float
    calm_resistance_kn: float
    max_wind_ms: float
    max_wave_m: float
    def __init__(self) -> None: ...

class Forecast:
    def __init__(
        self,
        first_h: float,
        step_h: float,
        *,
        current_east: npt.NDArray[np.float32] | None = ...,
        current_north: npt.NDArray[np.float32] | None = ...,
        wave_height: npt.NDArray[np.float32] | None = ...,
        wave_from: npt.NDArray[np.float32] | None = ...,
        wind_speed: npt.NDArray[np.float32] | None = ...,
        wave_period: npt.NDArray[np.float32] | None = ...,
    ) -> None: ...

class TravelTimeModel:
    #: The model's Capabilities (cpp/seaway/capabilities.hpp): static, symmetric, turn_penalty,
    #: time_dependent, smoothable.
    capabilities: ClassVar[dict[str, bool]]
    def __init__(self, forecast: Forecast, vessel: Vessel, best_speed_kn: float) -> None: ...

class FuelModel:
    #: The model's Capabilities (cpp/seaway/capabilities.hpp): static, symmetric, turn_penalty,
    #: time_dependent, smoothable.
    capabilities: ClassVar[dict[str, bool]]
    def __init__(
        self,
        forecast: Forecast,
        vessel: Vessel,
        settings_kn: list[float],
        rate_t_per_h: list[float],
        lambda_t_per_h: float,
        best_extra_kn: float,
    ) -> None: ...

class WaveDangerModel:
    #: The model's Capabilities (cpp/seaway/capabilities.hpp): static, symmetric, turn_penalty,
    #: time_dependent, smoothable.
    capabilities: ClassVar[dict[str, bool]]
    def __init__(self, forecast: Forecast, ship_length_m: float, speed_kn: float) -> None: ...

class ZonedTravelTimeModel:
    #: The model's Capabilities (cpp/seaway/capabilities.hpp): static, symmetric, turn_penalty,
    #: time_dependent, smoothable.
    capabilities: ClassVar[dict[str, bool]]
    def __init__(
        self,
        model: TravelTimeModel,
        mask: npt.NDArray[np.uint8],
        near: npt.NDArray[np.uint8],
        closes_h: list[float],
        opens_h: list[float],
    ) -> None: ...

class IceSeasonModel:
    #: The model's Capabilities (cpp/seaway/capabilities.hpp): static, symmetric, turn_penalty,
    #: time_dependent, smoothable.
    capabilities: ClassVar[dict[str, bool]]
    def __init__(
        self,
        hours_per_km: npt.NDArray[np.float32],
        valid_from_h: list[float],
        min_hours_per_km: float,
        max_hours_per_km: float = -1.0,
        closed_for: npt.NDArray[np.int16] | None = None,
    ) -> None: ...

class IceWeatherModel:
    #: The model's Capabilities (cpp/seaway/capabilities.hpp): static, symmetric, turn_penalty,
    #: time_dependent, smoothable.
    capabilities: ClassVar[dict[str, bool]]
    def __init__(
        self, ice: IceSeasonModel, forecast: Forecast, vessel: Vessel, min_hours_per_km: float
    ) -> None: ...

#: Every model the router is instantiated for (cpp/models.hpp).
Model = (
    MaxCost
    | MeanCost
    | IntegralCost
    | LengthCost
    | EnteredPixelCost
    | TravelTimeModel
    | FuelModel
    | WaveDangerModel
    | IceSeasonModel
    | IceWeatherModel
    | ZonedTravelTimeModel
)
#: The static models (capabilities: static): the bidirectional search.
StaticModel = MaxCost | MeanCost | IntegralCost | LengthCost | EnteredPixelCost
#: The time models (capabilities: time_dependent, smoothable): legs sailed on the clock and
#: smoothing (TimedLegs).
TimeModel = TravelTimeModel | ZonedTravelTimeModel | IceSeasonModel | IceWeatherModel
#: The raster rules (capabilities: static, symmetric, turn_penalty, smoothable): landmarks, turn
#: penalties, leg pricing and smoothing.
RasterRule = MaxCost | MeanCost | IntegralCost | LengthCost

def label_spares() -> tuple[list[int], int]: ...

class PreparedChart:
    @property
    def workspaces(self) -> int: ...
    def route(
        self,
        model: Model,
        start: int,
        target: int,
        heuristic_weight: float,
        cancel: CancelToken | None = None,
    ) -> QueryResult: ...
    def routes(
        self, model: Model, start: int, targets: list[int], cancel: CancelToken | None = None
    ) -> list[QueryResult]: ...
    def field(
        self, model: Model, start: int, cancel: CancelToken | None = None
    ) -> tuple[npt.NDArray[np.float64], SearchStats]: ...
    def prune_collinear(self, model: Model) -> bool: ...
    def forget_pruned(self, model: Model) -> None: ...
    def skip_table(self, model: Model) -> npt.NDArray[np.uint16] | None: ...
    @property
    def cost_range(self) -> tuple[float, float, int]: ...
    @property
    def least_cost_share(self) -> float: ...
    @property
    def clearance(self) -> npt.NDArray[np.uint8]: ...
    def route_bidirectional(
        self, model: StaticModel, start: int, target: int, astar: bool, cancel: CancelToken | None = None
    ) -> QueryResult: ...
    def build_landmarks(
        self, model: RasterRule, count: int, seed: int, cancel: CancelToken | None = None
    ) -> Landmarks: ...
    def route_landmarks(
        self,
        model: RasterRule,
        landmarks: Landmarks,
        start: int,
        target: int,
        bidirectional: bool,
        cancel: CancelToken | None = None,
    ) -> QueryResult: ...

class Landmarks:
    @property
    def pixels(self) -> list[int]: ...
    @property
    def bytes(self) -> int: ...
    @property
    def largest(self) -> float: ...
    @property
    def table(self) -> npt.NDArray[np.float32]: ...

class LegPricer:
    def __init__(
        self, model: RasterRule, land: npt.NDArray[np.uint8] | None, grid: Geometry, half: int
    ) -> None: ...
    def leg(self, r0: float, c0: float, r1: float, c1: float) -> tuple[float, float]: ...
    def smooth(
        self,
        vertices: npt.ArrayLike,
        step_cost: npt.ArrayLike,
        candidates: npt.ArrayLike,
        refine: bool,
        max_sweeps: int,
    ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], int]: ...

class TimedLegs:
    def __init__(self, router: PreparedChart, model: TimeModel, closed: npt.NDArray[np.uint8]) -> None: ...
    def arrive(self, r0: float, c0: float, r1: float, c1: float, depart_h: float) -> float: ...
    def smooth(
        self,
        vertices: npt.ArrayLike,
        arrive_h: npt.ArrayLike,
        leave_h: npt.ArrayLike,
        fixed: npt.ArrayLike,
        candidates: npt.ArrayLike,
    ) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.float64], npt.NDArray[np.float64], int]: ...

def make_router(
    cost: npt.NDArray[np.float32] | npt.NDArray[np.float64],
    land: npt.NDArray[np.uint8] | None,
    grid: Geometry,
    neighbourhood: int,
    directions: str,
    land_rule: str,
) -> PreparedChart: ...
def max_pair_costs(a: npt.ArrayLike, b: npt.ArrayLike, length: npt.ArrayLike) -> npt.NDArray[np.float64]: ...
def mean_pair_costs(a: npt.ArrayLike, b: npt.ArrayLike, length: npt.ArrayLike) -> npt.NDArray[np.float64]: ...
def length_pair_costs(
    a: npt.ArrayLike, b: npt.ArrayLike, length: npt.ArrayLike
) -> npt.NDArray[np.float64]: ...
def route_turns(
    router: PreparedChart,
    model: RasterRule,
    start: int,
    target: int,
    heuristic_weight: float,
    angle_deg: list[float],
    cost: list[float],
    incoming: int = -1,
    cancel: CancelToken | None = None,
) -> QueryResult: ...
def offset_index(router: PreparedChart, di: int, dj: int) -> int: ...
def route_least_danger(
    router: PreparedChart,
    model: TravelTimeModel | ZonedTravelTimeModel,
    danger_wind_ms: float,
    danger_wave_m: float,
    start: int,
    target: int,
    heuristic_weight: float,
    cancel: CancelToken | None = None,
) -> tuple[QueryResult, npt.NDArray[np.float64]]: ...
def stencil(
    k: int, directions: str
) -> list[tuple[int, int, list[tuple[int, int]], list[tuple[int, int, float]]]]: ...
def haversine_km(lat1: float, lon1: float, lat2: float, lon2: float) -> float: ...
def khokhlov_speed_kn(v0_kn: float, h3_m: float, q_rad: float, displacement_t: float) -> float: ...
def stawave1_speed_kn(
    v0_kn: float, hs_m: float, beam_m: float, length_m: float, calm_resistance_kn: float
) -> float: ...
def speed_over_ground_kn(v_kn: float, current_kn: float, q_rad: float) -> float: ...
def wave_danger(
    hs_m: float, wave_length_m: float, alpha_rad: float, ship_length_m: float, speed_kn: float
) -> float: ...

#: The search labels' memory strategy this build uses: "linux-madvise" or "portable-calloc".
page_strategy: str
