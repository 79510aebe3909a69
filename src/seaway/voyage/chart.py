"""OpenChart: a chart file opened for routing (seaway.open_chart) — its grid, CRS, land, ice and
what reading it assumed — and the options it was opened with (ChartOptions)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from ..errors import ChartError
from ..ice.concentration import DEFAULT_STAGE
from ..ice.forms import DEFAULT_FAST_ICE, check_fast_ice
from ..ice.impact import chart_impact, ice_impact
from .chartfield import arrival_field, time_cost
from .projected import in_km
from .route import route_chart
from .timing import concentration_closed

if TYPE_CHECKING:
    import xarray as xr

    from ..result.route import Route
    from ..vessel import Vessel
    from .projected import Projection


@dataclass(frozen=True)
class ChartOptions:
    """How a chart file is read: one object for the options every command and API shares.

    variable: the variable holding the cost per unit length (NaN/inf impassable; GeoTIFF: the
        band number); None: the ice of a stage-of-development or concentration chart, else the
        file's only 2-D variable.
    land_variable: the variable holding the land mask (default `land`, a CF land_binary_mask or
        a ROMS mask).
    grid: (south, north, west, east, resolution) in degrees to rasterise a SIGRID-3 chart onto
        (default: the box around the route's ends, seaway.ice.routegrid; without ends the
        chart's extent at 1/1000 of its longer side).
    fast_ice: the stage of fast ice of unknown stage (seaway.ice.forms): "nearby", "closed" or a
        WMO stage code.
    assume_stage: the WMO stage assumed for the ice of a concentration-only chart (default 93).
    depth, depth_variable, depth_positive: a bathymetry file resampled onto the chart (the
        shallowest depth in each pixel), its variable and sign (seaway.depth).
    land: a finer coastline merged with the chart's land (seaway.voyage.coast): None (default)
        the package's coastline where it is finer than the chart's pixels; "chart" the chart's
        own land only; or a file: a land mask (NetCDF, GeoTIFF, 1 = land) or coast polygons
        (shapefile, GeoPackage)."""

    variable: str | None = None
    land_variable: str | None = None
    grid: tuple[float, float, float, float, float] | None = None
    fast_ice: str | float = DEFAULT_FAST_ICE
    assume_stage: float | None = None
    depth: str | None = None
    depth_variable: str | None = None
    depth_positive: str | None = None
    land: str | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "fast_ice", check_fast_ice(self.fast_ice))
        if self.grid is not None:
            south, north, west, east, res = (float(v) for v in self.grid)
            if not (south < north and west < east and res > 0):
                raise ChartError(f"grid needs SOUTH < NORTH, WEST < EAST and RES > 0, got {self.grid!r}")


@dataclass(eq=False)
class OpenChart:
    """A chart opened for routing (seaway.open_chart): `route(start, end, ...)` gives the same
    Route as ``seaway route``.

    source: the file (or "kara"); description: what it is and what the cost is.
    layers: the chart's Dataset (SIGRID-3 CT, SA, ... land; a concentration chart as ice), which
        also describes the ends; ice: how the ice is priced ("stage", "sigrid", "concentration")
        or None for a cost raster; fixed_cost: the cost raster of a chart that is not ice.
    land: the land mask (DataArray, True = land) or None; projection: the CRS of a projected
        chart (routed on its own grid in km, ends and outputs in lat/lon) or None.
    environment: variables reported along each leg; date: the chart's date ("" if it has none).
    notes: what reading the chart assumed or decided, in words (``seaway route`` prints them).
    depth: the bathymetry on the chart's grid (m, positive down) when opened with one."""

    source: str
    description: str
    options: ChartOptions = field(default_factory=ChartOptions)
    layers: xr.Dataset | None = None
    vessel: str | None = None
    ice: str | None = None
    concentration: str | None = None
    fixed_cost: xr.DataArray | None = None
    land: xr.DataArray | None = None
    environment: dict[str, Any] = field(default_factory=dict)
    projection: Projection | None = None
    date: str = ""
    notes: list[str] = field(default_factory=list)
    depth: xr.DataArray | None = None
    #: A 2-D DataArray on the grid the route is searched on (projected charts: y/x in km).
    grid: xr.DataArray | None = None
    _costs: dict[str, xr.DataArray] = field(default_factory=dict, repr=False)
    #: The last least-time search set up by arrival_field: [options, what it built] (chartfield).
    _searched: list[Any] = field(default_factory=list, repr=False)

    def __getstate__(self) -> dict[str, Any]:
        """Pickled (to Dask workers) without the kept search, which the worker builds again."""
        return {**self.__dict__, "_searched": []}

    @property
    def is_ice(self) -> bool:
        """Is the route's cost the chart's ice, priced for an ice class (not a cost variable)?"""
        return self.ice is not None

    @property
    def crs(self) -> Any:
        """The chart's pyproj CRS when it is projected, else None (lat/lon or planar pixels)."""
        return None if self.projection is None else self.projection.crs

    def ice_class(self, vessel: str | None = None) -> str | None:
        """The class the chart's ice is priced for: `vessel`, else the one it was opened with,
        else Arc7 on stage charts (a concentration chart needs one: ChartError)."""
        if not self.is_ice:
            if vessel:
                raise ChartError(
                    f"{self.source} is a cost raster ({self.description}); an ice class applies to a "
                    "stage-of-development or concentration chart: give no vessel class"
                )
            return None
        cls = vessel or self.vessel
        if cls is None and self.ice == "concentration":
            stage = self.options.assume_stage or DEFAULT_STAGE
            raise ChartError(
                f"{self.source}: {self.concentration} is a sea-ice concentration (CF sea_ice_area_fraction), "
                "not a cost per unit length (open water would cost nothing); give --vessel CLASS (e.g. "
                f"Arc7) to turn it into an ice chart for that class, its ice assumed to be of WMO stage "
                f"{stage:g} (--assume-stage CODE to change)"
            )
        return cls or "Arc7"

    @property
    def cost(self) -> xr.DataArray:
        """The cost per unit length routes are searched on by default (cost_for(None))."""
        return self.cost_for(None)

    def cost_for(self, vessel: str | None = None, *, concentration_limit: bool = False) -> xr.DataArray:
        """The cost per unit length the route is searched on: the cost raster, or the ice priced
        for `vessel`'s class (Grinyak et al. 2022's impact; inf where the class may not go).
        concentration_limit: also inf where the total concentration is over the class's limit
        for independent navigation (its max_concentration, Grinyak et al. 2022 Table 1), as a
        season closes it by default."""
        cls = self.ice_class(vessel)
        if cls is None:
            assert self.fixed_cost is not None
            return self.fixed_cost
        if concentration_limit:
            return concentration_closed(self, cls, self.cost_for(cls))
        if cls not in self._costs:
            try:
                if self.ice == "stage":
                    assert self.layers is not None
                    u = ice_impact(self.layers.stage_of_development, cls)
                else:
                    u = chart_impact(self.layers, cls, fast_ice=self.options.fast_ice)
            except ValueError as exc:
                raise ChartError(str(exc)) from None
            if self.projection is not None:
                u = in_km(u)
            self._costs[cls] = u
        return self._costs[cls]

    def route(self, start: tuple[float, float], end: tuple[float, float], **options: Any) -> Route:
        """The route from `start` to `end` (lat, lon; ROW, COL on a planar chart without a
        projection), as ``seaway route`` finds it: ends checked and snapped, the no-route
        explanation, smoothing, times in the ice. Options: seaway.voyage.route.route_chart."""
        return route_chart(self, start, end, **options)

    def arrival_field(self, start: tuple[float, float], **options: Any) -> xr.DataArray:
        """Hours the ship takes from `start` (lat, lon; ROW, COL on a planar chart without a
        projection) to every pixel: the isochrones of one chart, a DataArray in hours (units
        "h"; lat/lon coordinates, 2-D beside y/x in km on a projected chart), inf where the ship
        may not go or cannot reach. The model is route(objective="time")'s: options vessel,
        speed_kn, escort, escort_speed_kn, stage_thickness, draft_m, ukc_m,
        concentration_limit, neighbourhood and
        snap_km (a start the ship may not use moves at most that far; None: refused, naming
        why) as route() takes them; route(..., objective="time", smooth=False) to a pixel costs
        its value there. One search serves every destination (seaway.fleet.od_matrix)."""
        return arrival_field(self, start, **options)

    def hours_per_km(self, vessel: Vessel | str | None = None, **options: Any) -> xr.DataArray:
        """The hours per km the least-time route (route(objective="time")) and arrival_field
        search for `vessel`: the ship's speed in each pixel's ice (seaway.ice.speed), inf where
        its class may not go (the chart's impact is inf: land, ice closed to the class) or it
        has no speed of its own there (escort=True: the escort's speed); per true km on a
        projected chart (y/x in km). options: speed_kn, escort, escort_speed_kn,
        stage_thickness, draft_m, ukc_m, concentration_limit (True: ice over the class's
        concentration limit closed too, as a season closes it by default). seaway.cost_field on it, with the chart's land, is
        arrival_field; 1 / seaway.ice.ice_speed is not: a speed does not close what the class
        may not enter."""
        return time_cost(self, vessel=vessel, **options)[0]
