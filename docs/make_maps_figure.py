"""Draw docs/ice_chart_map.png: the demo's Arc7 route on a polar stereographic map of the
built-in winter chart, ice in the WMO colour code by stage of development (seaway.plot).

Run from the repository root: python docs/make_maps_figure.py (needs seaway[plot])."""

import seaway
from seaway.cli.demo import KARA_GATE, VILKITSKY_STRAIT, nearest_water
from seaway.plot import plot_route
from seaway.samples import ice_impact, kara_sea

ds = kara_sea((950, 1150))  # half the default resolution: the same ice, a smaller file
u = ice_impact(ds.stage_of_development, "Arc7")
ends = [nearest_water(ds, lat, lon)[:2] for _, lat, lon in (KARA_GATE, VILKITSKY_STRAIT)]
(s, e) = [(float(ds.lat[r]), float(ds.lon[c])) for r, c in ends]
r = seaway.route(u, s, e, land=ds.land).smoothed().with_environment(ds)
r.name = "Arc7, Kara Gate -> Vilkitsky Strait"
plot_route(r, "docs/ice_chart_map.png", dpi=80)  # stage of development from the environment
print("docs/ice_chart_map.png:", round(r.cost, 1), round(r.length, 1), r.course_changes)
