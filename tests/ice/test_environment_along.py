"""The environment along a route (issue 19): categorical layers give one category per leg (the
governing stage, the most frequent form), legs without values give "none" instead of crashing,
and summarize() measures the ice along the legs of a smoothed route as dense sampling does."""

import csv
import io
import json

import numpy as np
import pytest
import xarray as xr

import seaway
from seaway import export
from seaway._core import haversine_km
from seaway.base import sphere
from seaway.ice import chart_impact
from seaway.icenav import summary

DMI_SUMMER = ("ice_charts_sigrid3", "dmi_greenland", "201307222045_CapeFarewell_RIC.shp")


@pytest.mark.needs_data(*DMI_SUMMER)
def test_a_route_through_open_water_of_a_real_chart_reports_none(shared_data, tmp_path):
    """DMI's July chart: the route keeps to open water, where SA, FA and the partials are NaN;
    every output used to fail with 'zero-size array to reduction operation maximum'."""
    pytest.importorskip("pyogrio")
    from seaway.ice.grids import latlon_grid
    from seaway.ice.sigrid import read_sigrid3

    ds = read_sigrid3(str(shared_data.joinpath(*DMI_SUMMER)), latlon_grid(57.7, 62.6, -52.7, -37.3, 0.1))
    r = seaway.route(chart_impact(ds, "Arc7"), (62.45, -51.15), (57.75, -39.75), land=ds.land)
    r = r.with_environment(ds)
    legs = r.legs()
    assert all(leg.environment["SA"].name == "none" and np.isnan(leg.environment["CA"].max) for leg in legs)
    assert all(leg.environment["CT"] == (0.0, 0.0) for leg in legs)  # open water: CT 0
    s = r.summary()
    assert s["governing_SA"] == "none" and s["max_CA"] is None and s["max_CT"] == 0.0
    table = str(r)
    assert "SA (governing)" in table and "FA (most frequent)" in table
    props = export.geojson(r)["properties"]
    assert props["governing_SA"] == "none" and "max_CA" not in props
    text = export.csv_text(r)  # '#' lines head it: the route's figures, ends and assumptions
    rows = list(csv.DictReader(x for x in io.StringIO(text) if not x.startswith("#")))
    assert rows[1]["SA_governing"] == "" and rows[1]["SA_name"] == "none" and rows[1]["CA_max"] == ""
    json.dumps(export.geojson(r))  # plain JSON
    pytest.importorskip("folium")
    r.to_html(tmp_path / "r.html")
    assert "SA: up to none" in (tmp_path / "r.html").read_text()


def _band_chart():
    """Open water at 70-76 N, 60-80 E with a band of first-year ice (SA 86, FA 04) at 66-70 E,
    and a 2-degree island in the middle of the way (so the route turns and is smoothed)."""
    lat, lon = np.round(np.arange(70.05, 76, 0.1), 2), np.round(np.arange(60.05, 80, 0.1), 2)
    LON, LAT = np.meshgrid(lon, lat)
    band = (LON > 66) & (LON < 70)
    land = (LAT > 72) & (LAT < 74) & (LON > 72) & (LON < 75)
    dims = ("lat", "lon")
    ct = np.where(band, 10.0, 0.0)
    return xr.Dataset(
        {
            "CT": (dims, ct),
            "CA": (dims, ct),
            "SA": (dims, np.where(band, 86.0, np.nan)),
            "FA": (dims, np.where(band, 4.0, np.nan)),
            "land": (dims, land),
        },
        coords={"lat": lat, "lon": lon},
    )


def _dense_km(route, inside, n=2000):
    """km of the route's legs (great circles) where inside(lat, lon): n points per leg."""
    total, c = 0.0, route.coords
    for a, b in zip(c[:-1], c[1:]):
        lat, lon = sphere.intermediate(a[0], a[1], b[0], b[1], (np.arange(n) + 0.5) / n)
        total += haversine_km(a[0], a[1], b[0], b[1]) * np.mean(inside(lat, lon))
    return float(total)


def test_summarize_a_smoothed_route_agrees_with_dense_sampling():
    ds = _band_chart()
    raw = seaway.route(chart_impact(ds, "Arc7"), (73.0, 61.0), (73.5, 79.0), land=ds.land)
    r = raw.smoothed()
    assert len(r.waypoint_index) < len(raw.pixels) / 5  # long legs: the case that was wrong
    s = summary.summarize(r, ds)
    truth = _dense_km(r, lambda lat, lon: (lon > 66) & (lon < 70))
    assert truth > 100
    assert s["by_stage"]["first-year ice"]["distance"] == pytest.approx(truth, rel=0.02)
    assert sum(v["distance"] for v in s["by_stage"].values()) == pytest.approx(r.length)
    legs = r.with_environment(ds).legs()
    crossing = [leg for leg in legs if leg.environment["SA"].name == "first-year ice"]
    assert crossing and all(leg.environment["FA"].name == "medium floe" for leg in crossing)
    assert all(leg.environment["SA"].rule == "governing" for leg in legs)
