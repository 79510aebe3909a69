"""The issue's reproducers under a real address-space limit (RLIMIT_AS, 2 GiB): refused with one
line naming the figure and the fix, before anything large is allocated. Before, `seaway route
DMI.shp ... --grid=56,64,-56,-37,0.001` grew past 6 GiB in 23 s and was killed, and at 0.0001
ended in numpy's "Unable to allocate 56.6 GiB" traceback. Each child first does the real work
at a size that fits (the baseline, measured in the same process), then the refusals: they must
take less time than the baseline and leave the peak resident memory where the baseline put it."""

import json
import os
import re
import resource
import subprocess
import sys
import textwrap

import pytest

from seaway.base.memory import SEARCH, SYNTHETIC
from seaway.ice.grids import CHART

LIMIT = 2 * 2**30
#: AddressSanitizer reserves terabytes of address space for its shadow memory: a child under
#: RLIMIT_AS cannot start with it (.ci/sanitize preloads libasan); the tests run without it.
UNDER_ASAN = "asan" in os.environ.get("LD_PRELOAD", "")
LINUX_ONLY = pytest.mark.skipif(
    not sys.platform.startswith("linux") or UNDER_ASAN, reason="RLIMIT_AS as Linux counts it, without ASan"
)
DMI = ("ice_charts_sigrid3", "dmi_greenland", "201304100920_CapeFarewell_RIC.shp")

CHILD = textwrap.dedent(
    """
    import contextlib, io, json, resource, sys, time
    from seaway.cli import main

    def peak_mb():
        return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024

    def run(argv):
        err = io.StringIO()
        t0 = time.perf_counter()
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
            status = main(argv)
        return dict(status=status, seconds=time.perf_counter() - t0, err=err.getvalue(), peak_mb=peak_mb())

    common, baseline, refused = json.loads(sys.argv[1])
    out = {"baseline": run(common + baseline)}
    out["refused"] = [run(common + r) for r in refused]
    print(json.dumps(out))
    """
)


def _child(common, baseline, refused):
    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (LIMIT, LIMIT))

    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")  # thread arenas: address space
    env.pop("SEAWAY_MEMORY_LIMIT", None)
    done = subprocess.run(
        [sys.executable, "-c", CHILD, json.dumps([common, baseline, refused])],
        preexec_fn=limit,
        env=env,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def _check(out):
    base = out["baseline"]
    assert base["status"] == 0, base["err"]
    for r in out["refused"]:
        lines = r["err"].strip().splitlines()
        assert r["status"] == 1 and "Traceback" not in r["err"], r["err"]
        # allocated nothing large: the peak is the baseline's; and it took less than the baseline
        assert r["peak_mb"] <= base["peak_mb"] + 50 and r["seconds"] < base["seconds"]
        yield lines[-1]


#: What the limit says: the address-space limit less what the process already maps (the
#: interpreter, numpy, GDAL), so its figure depends on the machine; parsed, not matched.
LEFT = (
    r"more than the (?P<cap>[\d.]+) (?P<unit>[GM])iB seaway may take \(what the 2\.0 GiB address-space "
    r"limit \(ulimit -v\) leaves: (?P=cap) (?P=unit)iB\); "
)


def _cap(match):
    return float(match["cap"]) * (2**30 if match["unit"] == "G" else 2**20)


@pytest.mark.cli
@pytest.mark.needs_data(*DMI)
@LINUX_ONLY
def test_the_issue_grids_are_refused_in_one_line_within_bounded_memory(shared_data):
    pytest.importorskip("pyogrio")
    common = [
        "route",
        str(shared_data.joinpath(*DMI)),
        "--from",
        "59.5,-44",
        "--to",
        "60.5,-48",
        "--vessel",
        "Arc7",
        "-q",
    ]
    out = _child(
        common,
        ["--grid=56,64,-56,-37,0.01"],
        [["--grid=56,64,-56,-37,0.001"], ["--grid=56,64,-56,-37,0.0001"]],
    )
    lines = list(_check(out))
    figures = [
        "8,000 x 19,000 pixels (152,000,000) needs about 19.3 GiB",
        "80,000 x 190,000 pixels (15,200,000,000) needs about 1.9 TiB",
    ]
    for line, figure in zip(lines, figures):
        m = re.fullmatch(
            rf"seaway route: error: a chart on a grid of {re.escape(figure)}, {LEFT}give a coarser grid "
            r"\(e\.g\. a resolution of (?P<res>[\d.]+) deg: (?P<rows>[\d,]+) x (?P<cols>[\d,]+) pixels\) or a smaller box",
            line,
        )
        assert m, line
        # the resolution named divides the box and its chart fits in what is left
        rows, cols = (int(m[k].replace(",", "")) for k in ("rows", "cols"))
        assert (rows, cols) == (round(8 / float(m["res"])), round(19 / float(m["res"])))
        assert rows * cols * CHART <= _cap(m) * 1.001


@pytest.mark.cli
@LINUX_ONLY
def test_samples_and_bench_sizes_are_refused_in_one_line_within_bounded_memory():
    out = _child(
        ["bench", "--neighbourhood", "3", "--repeat", "1"],
        ["--size", "600x700"],
        [["--size", "100000x100000"]],
    )
    (line,) = _check(out)
    m = re.fullmatch(
        r"seaway bench: error: the synthetic sea of 100,000 x 100,000 pixels \(10,000,000,000\) needs about "
        rf"763\.7 GiB, {LEFT}give a smaller shape, e\.g\. \((?P<rows>\d+), (?P=rows)\)",
        line,
    )
    assert m, line
    assert int(m["rows"]) ** 2 * (SYNTHETIC + SEARCH) <= _cap(m) * 1.001


def test_an_allocation_that_fails_anyway_ends_in_one_line(monkeypatch, capsys):
    """The backstop behind the estimates: a MemoryError (numpy's _ArrayMemoryError) ends in one
    line naming the fix, not a traceback."""
    from seaway.cli import main

    def allocate(*args, **kwargs):  # what numpy raises for a request the machine cannot hold
        raise MemoryError(
            "Unable to allocate 56.6 GiB for an array with shape (80000, 190000) and data type int32"
        )

    monkeypatch.setattr("seaway.cli.route.open_chart", allocate)
    assert main(["route", "kara", "--from", "70.3,58.49", "--to", "70.5,60", "-q"]) == 1
    assert capsys.readouterr().err.splitlines() == [
        "seaway route: error: out of memory (Unable to allocate 56.6 GiB for an array with shape (80000, "
        "190000) and data type int32); give a coarser grid, a smaller box or fewer charts, or set "
        "SEAWAY_MEMORY_LIMIT lower"
    ]
