"""Draw docs/demo_route.png: the demo's Arc7 route over the default chart's ice.

Run from the repository root: python docs/make_demo_figure.py (needs matplotlib)."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import seaway  # noqa: E402
from seaway.cli.demo import DEMO_SNAP_KM, KARA_GATE, VILKITSKY_STRAIT  # noqa: E402

chart = seaway.open_chart("kara", vessel="Arc7")  # the demo's chart and route
ds, u = chart.layers, chart.cost
r = chart.route(KARA_GATE[1:], VILKITSKY_STRAIT[1:], snap_km=DEMO_SNAP_KM, smooth=False)

fig, ax = plt.subplots(figsize=(9, 6.5), dpi=90)
extent = [float(ds.lon[0]), float(ds.lon[-1]), float(ds.lat[-1]), float(ds.lat[0])]
im = ax.imshow(np.where(ds.land, np.nan, u), extent=extent, aspect="auto", cmap="Blues", vmin=0, vmax=30)
ax.imshow(np.where(ds.land, 1.0, np.nan), extent=extent, aspect="auto", cmap="Greys", vmin=0, vmax=2)
ax.plot(r.coords[:, 1], r.coords[:, 0], color="crimson", lw=1.6, label=f"Arc7 route, {r.length:.0f} km")
ax.plot(*r.coords[0, ::-1], "o", color="crimson")
ax.plot(*r.coords[-1, ::-1], "s", color="crimson")
ax.set_xlabel("longitude, °E")
ax.set_ylabel("latitude, °N")
ax.set_title("seaway demo: Kara Gate → Vilkitsky Strait, Arc7, 5×5 stencil\n"
             "over the ice impact of Grinyak et al. (2022)")
fig.colorbar(im, ax=ax, label="ice impact u (open water 2 … thick first-year 30)")
ax.legend(loc="lower right")
fig.tight_layout()
fig.savefig("docs/demo_route.png")
print("docs/demo_route.png:", r.cost, r.length)
