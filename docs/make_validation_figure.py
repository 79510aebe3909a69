"""Draw docs/validation_voyages.png: published winter NSR voyages against seaway's routes.

Left: the synthetic February chart (tests/support/aari_winter.py) with the Arc7 LNG carrier's
quickest route Cape Dezhnev -> Sabetta (V6) and the route on the real NSIDC chart of 2021-12-31
(medium first-year ice assumed). Right: the published time of each voyage beside seaway's
(the middle of the stage's WMO thickness range; the whisker spans its lower to upper end).

Run from the repository root: python docs/make_validation_figure.py (needs matplotlib and the
[ice] extra; the NSIDC bars need ../shared/data)."""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pyproj  # noqa: E402
import shapely  # noqa: E402

import seaway  # noqa: E402
from seaway.vessel import load  # noqa: E402

sys.path.insert(0, "tests")
from support import aari_winter  # noqa: E402

SABETTA, DEZHNEV, BERING = (71.27, 72.07), (66.07, -169.65), (66.1, -169.5)
NSIDC = Path("../shared/data/sea_ice_concentration/seaice_conc_daily_nh_20211231_f17_v04r00.nc")
#: (label, vessel file, start, end, published h, escort kn, chart, stage of a concentration chart)
CASES = [
    ("V6 Feb 2021\nFeb chart", "arc7-lng-carrier", DEZHNEV, SABETTA, 274.0, 8.6, "feb", None),
    ("V5 Jan 2021\nFeb chart", "arc7-lng-carrier", SABETTA, DEZHNEV, 261.0, None, "feb", None),
    ("V5 Jan 2021\nNSIDC, 91", "arc7-lng-carrier", SABETTA, DEZHNEV, 261.0, None, "nsidc", 91),
    ("V5 Jan 2021\nNSIDC, 93", "arc7-lng-carrier", SABETTA, DEZHNEV, 261.0, None, "nsidc", 93),
    ("V9 Dec 2016\nNSIDC, 91", "arc7-shuttle-tanker", BERING, SABETTA, 312.0, 6.0, "nsidc", 91),
]
COLOURS = {
    "fast ice": "#c8c8c8",
    "flaw polynya": "#f4a6a6",
    "old ice": "#8c5a2b",
    "northern East Siberian Sea": "#a0703c",
}


def route(path, vessel, a, b, escort_kn, stage, rule="mid"):
    extra = {} if stage is None else {"assume_stage": stage}
    chart = seaway.open_chart(str(path), vessel=load(vessel), ends=(a, b), **extra)
    r = chart.route(
        a, b, objective="time", escort=escort_kn is not None, escort_speed_kn=escort_kn,
        stage_thickness=rule, snap_km=30,
    )  # fmt: skip
    return r


def draw_route(ax, r, crs=None, **style):
    """The route's legs as they were checked: straight in lat/lon, or in the chart's `crs`."""
    w = np.asarray(r.latlon if r.latlon is not None else r.coords, float)
    t = np.linspace(0, 1, 30)[:, None]
    if crs is None:
        w[:, 1] = np.unwrap(w[:, 1], period=360)
        dense = np.vstack([a + (b - a) * t for a, b in zip(w[:-1], w[1:])])
    else:
        to, back = (pyproj.Transformer.from_crs(*c, always_xy=True) for c in (("EPSG:4326", crs), (crs, "EPSG:4326")))
        xy = np.column_stack(to.transform(w[:, 1], w[:, 0]))
        xy = np.vstack([a + (b - a) * t for a, b in zip(xy[:-1], xy[1:])])
        lon, lat = back.transform(xy[:, 0], xy[:, 1])
        dense = np.column_stack([lat, lon])
    x, y = aari_winter.TO_PLANE.transform(dense[:, 1], dense[:, 0])
    ax.plot(np.asarray(x) / 1e3, np.asarray(y) / 1e3, **style)


def main():
    feb = Path("/tmp/aari_winter_february.shp")
    aari_winter.write(feb)
    geoms, _, names = aari_winter.build()
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(15, 6.2), dpi=90, gridspec_kw={"width_ratios": [1.6, 1]})
    for g, n in zip(geoms, names):
        colour = "#7fb77e" if n in aari_winter.LAND else COLOURS.get(n)
        if colour is None:
            sa = next(a for name, _, a in aari_winter.REGIONS if name == n)["SA"]
            colour = {"91": "#7aa7e0", "93": "#2f5fa8", "87": "#b9d7f5"}.get(sa, "#b9d7f5")
        for p in shapely.get_parts(g):
            x, y = p.exterior.xy
            ax.fill(np.asarray(x) / 1e3, np.asarray(y) / 1e3, fc=colour, ec="k", lw=0.15)
    r6 = route(feb, *CASES[0][1:4], CASES[0][5], None)
    draw_route(ax, r6, color="crimson", lw=1.8, label=f"V6 on the February chart: {r6.summary()['length_nm']:.0f} nm")
    if NSIDC.exists():
        rn = route(NSIDC, "arc7-lng-carrier", SABETTA, DEZHNEV, None, 91)
        draw_route(ax, rn, "EPSG:3411", color="gold", lw=1.8, ls="--", label=f"V5 on NSIDC 2021-12-31: {rn.summary()['length_nm']:.0f} nm")
    for name, (la, lo) in {"Sabetta": SABETTA, "Cape Dezhnev": DEZHNEV, "Vilkitsky Strait": (77.7, 104.0)}.items():
        x, y = aari_winter.TO_PLANE.transform(lo, la)
        ax.plot(x / 1e3, y / 1e3, "k*")
        ax.annotate(name, (x / 1e3, y / 1e3), xytext=(4, 4), textcoords="offset points", fontsize=8)
    ax.set_aspect("equal")
    ax.set_title("Synthetic AARI-style February chart: light blue thin, blue medium, dark blue thick\n"
                 "first-year ice; grey fast ice; pink flaw polynyas (young ice); brown old ice")  # fmt: skip
    ax.set_xlabel("km (Lambert equal-area, pole, 125 E)")
    ax.legend(loc="lower left", fontsize=8)
    labels, published, model, low, high = [], [], [], [], []
    for label, vessel, a, b, hours, escort, which, stage in CASES:
        path = feb if which == "feb" else NSIDC
        if which == "nsidc" and not NSIDC.exists():
            continue
        t = [route(path, vessel, a, b, escort, stage, rule).summary()["time_h"] for rule in ("lower", "mid", "upper")]
        labels.append(label)
        published.append(hours)
        model.append(t[1])
        low.append(t[1] - min(t))
        high.append(max(t) - t[1])
    x = np.arange(len(labels))
    bx.bar(x - 0.2, published, 0.4, color="#555555", label="published")
    bx.bar(x + 0.2, model, 0.4, yerr=[low, high], capsize=3, color="#2f5fa8", label="seaway (lower..upper thickness)")
    bx.set_xticks(x, labels, fontsize=8)
    bx.set_ylabel("voyage time, h")
    bx.set_title("Published time against seaway's")
    bx.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig("docs/validation_voyages.png")
    print("docs/validation_voyages.png:", dict(zip([s.replace("\n", " ") for s in labels], np.round(model, 1))))


if __name__ == "__main__":
    main()
