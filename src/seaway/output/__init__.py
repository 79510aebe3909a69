"""Outputs of a route: files (GeoJSON, GPX, CSV, RTZ, HTML), PNG maps and interactive HTML maps,
and the map style they share."""
