"""Draw docs/ice_chart_map.png: the demo's Arc7 route on a polar stereographic map of the
built-in winter chart, ice in the WMO colour code by stage of development (seaway.plot).

Run from the repository root: python docs/make_maps_figure.py (needs seaway[plot])."""

import dataclasses

import seaway
from seaway.cli.demo import DEMO_SNAP_KM, KARA_GATE, VILKITSKY_STRAIT
from seaway.plot import plot_route
from seaway.samples import ice_impact, kara_sea

ds = kara_sea((950, 1150))  # half the default resolution: the same ice, a smaller file
u = ice_impact(ds.stage_of_development, "Arc7")
ends = seaway.snap_ends(u, KARA_GATE[1:], VILKITSKY_STRAIT[1:], land=ds.land, max_km=DEMO_SNAP_KM).ends
r = seaway.route(u, *ends, land=ds.land).smoothed().with_environment(ds)
r = dataclasses.replace(r, name="Arc7, Kara Gate -> Vilkitsky Strait")
plot_route(r, "docs/ice_chart_map.png", dpi=80)  # stage of development from the environment
print("docs/ice_chart_map.png:", round(r.cost, 1), round(r.length, 1), r.course_changes)
