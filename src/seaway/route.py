"""The Route a search returns: its pixels, coordinates, cost and length."""

from __future__ import annotations

import json
from dataclasses import dataclass, field

import numpy as np

from ._chart import Chart
from ._core import haversine_km


@dataclass
class Route:
    chart: Chart = field(repr=False)
    cost: float
    pixels: np.ndarray  # (n, 2) row, col; both ends included
    method: str = "astar"
    neighbourhood: int = 5
    edge_cost: str = "max"
    stats: dict = field(default_factory=dict, repr=False)

    @property
    def coords(self) -> np.ndarray:
        """(n, 2) lat/lon (geographic charts) or y/x (planar charts) of the route's pixels."""
        return self.chart.pixel_coords(self.pixels)

    @property
    def geographic(self) -> bool:
        return self.chart.geographic

    @property
    def leg_lengths(self) -> np.ndarray:
        """Length of each step: km on geographic charts, grid units on planar charts."""
        if len(self.pixels) < 2:
            return np.zeros(0)
        c = self.coords
        if self.geographic:
            return np.array([haversine_km(a[0], a[1], b[0], b[1]) for a, b in zip(c[:-1], c[1:])])
        g = self.chart.grid  # planar charts never wrap
        d = np.diff(self.pixels, axis=0).astype(float)
        return np.hypot(d[:, 0] * g.dy, d[:, 1] * g.dx)

    @property
    def length(self) -> float:
        """Total length: km on geographic charts, grid units on planar charts."""
        return float(self.leg_lengths.sum())

    def to_geojson(self) -> dict:
        """A GeoJSON Feature (LineString) with the route's cost and length as properties.

        Geographic charts give [lon, lat] positions with longitudes made continuous along the
        route (a route across the antimeridian runs past 180 rather than jumping back)."""
        c = self.coords
        if self.geographic:
            lon = np.degrees(np.unwrap(np.radians(c[:, 1])))
            positions = np.column_stack([lon, c[:, 0]])
        else:
            positions = c[:, ::-1]
        props = {"cost": self.cost, "length": self.length,
                 "length_units": "km" if self.geographic else "grid units",
                 "method": self.method, "neighbourhood": self.neighbourhood,
                 "edge_cost": self.edge_cost}
        coords = positions.tolist()
        if len(coords) == 1:
            coords = coords * 2  # a LineString needs two positions; start == end
        return {"type": "Feature", "geometry": {"type": "LineString", "coordinates": coords},
                "properties": props}

    def to_geojson_str(self) -> str:
        return json.dumps(self.to_geojson())
