"""The per-voyage tables of benchmarks/test_voyages.py, as Markdown lines (printed at the end of
the run by conftest.py, pasted into benchmarks/README.md)."""

import statistics

EXACT = ("dijkstra", "astar", "bidirectional", "landmarks")


def _ratio_table(rows, season):
    cases = []
    for r in rows:
        if r["season"] == season and r["chart"] != "skimage" and (r["chart"], r["method"]) not in cases:
            cases.append((r["chart"], r["method"]))
    head = ["voyage", "skimage s"] + [f"{c} {m}" for c, m in cases]
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for v in sorted({r["voyage"] for r in rows if r["season"] == season}):
        mine = {(r["chart"], r["method"]): r for r in rows if r["season"] == season and r["voyage"] == v}
        cells = [str(v) if v else "0 (corner)", f"{mine['skimage', 'peer']['wall']:.3f}"]
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
        mine = {
            r["method"]: r
            for r in rows
            if r["season"] == season and r["voyage"] == v and r["chart"] == "prepared"
        }
        out.append(
            "| "
            + " | ".join([str(v)] + [f"{mine[m]['settled']:,}, {mine[m]['ns']:.0f}" for m in EXACT])
            + " |"
        )
    return out


def goals(rows):
    """The issue's goals, read off the rows: auto's ratios and auto against the fastest exact method."""
    out = []
    for season in dict.fromkeys(r["season"] for r in rows):

        def pick(chart, voyage=None, method="auto"):
            return [
                r
                for r in rows
                if r["season"] == season
                and r["chart"] == chart
                and r["method"] == method
                and (voyage is None or r["voyage"] == voyage)
            ]

        for chart in ("fresh", "prepared"):
            corner, every = pick(chart, 0), pick(chart)
            if not corner:
                continue
            out.append(
                f"{season}, {chart} chart, auto: corner voyage {corner[0]['ratio']:.3f} x skimage, "
                f"median over {len(every)} voyages {statistics.median(r['ratio'] for r in every):.3f}, "
                f"worst {max(r['ratio'] for r in every):.3f}"
            )
            worst = (0.0, None)
            for r in every:
                exact = [x for m in EXACT for x in pick(chart, r["voyage"], m)]
                fastest = min(exact, key=lambda x: x["wall"])
                slow = r["wall"] / fastest["wall"]
                if slow > worst[0]:
                    worst = (
                        slow,
                        f"voyage {r['voyage']}: auto ({r['used']}) {r['wall']:.3f} s, "
                        f"{fastest['method']} {fastest['wall']:.3f} s",
                    )
            out.append(f"  auto / fastest exact method, worst voyage: {worst[0]:.2f} ({worst[1]})")
    return out


def lines(voyages):
    rows = voyages.get("rows", [])
    if not rows:
        return []
    out = ["Wall time / scikit-image's on the same voyage (auto: the method it used):"]
    for season in dict.fromkeys(r["season"] for r in rows):
        if any(r["season"] == season for r in rows):
            out += ["", f"{season}:", ""] + _ratio_table(rows, season)
            out += ["", f"{season}, prepared chart: pixels settled and CPU ns per settled pixel:", ""]
            out += _work_table(rows, season)
    return out + [""] + goals(rows) + voyages.get("notes", [])
