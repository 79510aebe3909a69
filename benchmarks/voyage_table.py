"""The tables of benchmarks/test_voyages.py, as Markdown lines (printed at the end of the run by
conftest.py, pasted into benchmarks/README.md): a summary per chart, then per chart the ratios
voyage by voyage and the prepared chart's pixels settled and CPU ns per pixel."""

import statistics

EXACT = ("dijkstra", "astar", "bidirectional", "landmarks")
PEERS = ("tcod dijkstra", "tcod astar", "pyastar2d")


def _pick(rows, season, chart, method, voyage=None):
    return [
        r
        for r in rows
        if r["season"] == season
        and r["chart"] == chart
        and r["method"] == method
        and (voyage is None or r["voyage"] == voyage)
    ]


def _auto_vs_fastest(rows, season, chart):
    """The worst voyage's auto wall time / the fastest exact method's, and that voyage."""
    worst = (0.0, "")
    for r in _pick(rows, season, chart, "auto"):
        exact = [x for m in EXACT for x in _pick(rows, season, chart, m, r["voyage"])]
        fastest = min(exact, key=lambda x: x["wall"])
        slow = r["wall"] / fastest["wall"]
        if slow > worst[0]:
            worst = (slow, f"v{r['voyage']} {r['used']} vs {fastest['method']}")
    return worst


def summary(rows):
    head = [
        "chart",
        "tuned / held out",
        "skimage s (v0)",
        "fresh auto v0 / median / worst",
        "prepared auto v0 / median / worst",
        "auto / fastest, worst: fresh; prepared",
        "peers / skimage, median: tcod D, tcod A*, pyastar2d",
        "auto decision ms; prepare ms",
    ]
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for season in dict.fromkeys(r["season"] for r in rows):
        cells = [season, "tuned" if _pick(rows, season, "peer", "skimage")[0]["tuned"] else "held out"]
        cells.append(f"{_pick(rows, season, 'peer', 'skimage', 0)[0]['wall']:.3f}")
        for chart in ("fresh", "prepared"):
            every = [r["ratio"] for r in _pick(rows, season, chart, "auto")]
            v0 = _pick(rows, season, chart, "auto", 0)[0]["ratio"]
            cells.append(f"{v0:.3f} / {statistics.median(every):.3f} / {max(every):.3f}")
        f, p = (_auto_vs_fastest(rows, season, c) for c in ("fresh", "prepared"))
        cells.append(f"{f[0]:.2f} ({f[1]}); {p[0]:.2f} ({p[1]})")
        peers = [[r["ratio"] for r in _pick(rows, season, "peer", m)] for m in PEERS]
        cells.append(", ".join(f"{statistics.median(p):.2f}" if p else "-" for p in peers))
        dec = statistics.median(r["wall"] for r in _pick(rows, season, "prepared", "decision"))
        prep = statistics.median(r["wall"] for r in _pick(rows, season, "fresh", "prepare"))
        cells.append(f"{1e3 * dec:.2f}; {1e3 * prep:.1f}")
        out.append("| " + " | ".join(cells) + " |")
    return out


def _ratio_table(rows, season):
    cases = []
    for r in rows:
        if r["season"] == season and r["method"] not in ("decision", "prepare", "skimage"):
            if (r["chart"], r["method"]) not in cases:
                cases.append((r["chart"], r["method"]))
    head = ["voyage", "skimage s"] + [f"{c} {m}" for c, m in cases]
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for v in sorted({r["voyage"] for r in rows if r["season"] == season}):
        mine = {(r["chart"], r["method"]): r for r in rows if r["season"] == season and r["voyage"] == v}
        cells = [str(v) if v else "0 (corner)", f"{mine['peer', 'skimage']['wall']:.3f}"]
        for c in cases:
            r = mine[c]
            used = f" ({r['used']})" if c[1] == "auto" else ""
            cells.append(f"{r['ratio']:.3f}{used}")
        out.append("| " + " | ".join(cells) + " |")
    return out


def _work_table(rows, season):
    head = ["voyage"] + [f"{m}: settled, ns/pixel" for m in EXACT]
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for v in sorted({r["voyage"] for r in rows if r["season"] == season}):
        mine = {r["method"]: r for r in _pick_all(rows, season, "prepared", v)}
        out.append(
            "| "
            + " | ".join([str(v)] + [f"{mine[m]['settled']:,}, {mine[m]['ns']:.0f}" for m in EXACT])
            + " |"
        )
    return out


def _pick_all(rows, season, chart, voyage):
    return [r for r in rows if r["season"] == season and r["chart"] == chart and r["voyage"] == voyage]


def lines(voyages):
    rows = voyages.get("rows", [])
    if not rows:
        return []
    out = ["Summary: wall time / scikit-image's on the same voyage (v0: the corner voyage):", ""]
    out += summary(rows)
    for season in dict.fromkeys(r["season"] for r in rows):
        out += ["", f"{season}: wall time / scikit-image's (auto: the method it used):", ""]
        out += _ratio_table(rows, season)
        out += ["", f"{season}, prepared chart: pixels settled and CPU ns per settled pixel:", ""]
        out += _work_table(rows, season)
    return out + [""] + voyages.get("notes", [])
