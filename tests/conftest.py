"""Shared test set-up.

Layout: one folder per area (engine/, chart/, models/, ice/, weather/, depth/, constraints/,
output/, fleet/, cli/, compat/), no __init__.py in them: pytest imports each test file by its
basename ("prepend" import mode), so test file basenames must be unique across tests/ (pytest
stops with "import file mismatch" otherwise). Helpers live in the package tests/support/ and are
imported one way, `from support.reference import RefGraph` (pyproject: pythonpath = ["tests"]).

Real data (../shared/data, next to the repository; SEAWAY_SHARED_DATA overrides). One way:
- a test that reads it carries the marker `@pytest.mark.needs_data` (or a module's
  `pytestmark = pytest.mark.needs_data`); `@pytest.mark.needs_data("ocean_model", "x.nc")`
  names the file it needs. It is skipped when the folder (or that file) is absent;
- it gets the folder from the session fixture `shared_data` (a pathlib.Path; the fixture also
  skips when the folder is absent), or, where the path is needed at import time (parametrize
  over the files), from `support.data.SHARED_DATA`.
Select with `-m needs_data` / `-m "not needs_data"`.

Markers (registered in pyproject.toml, --strict-markers): slow (> ~5 s on the reference machine),
cli (runs the command line: `seaway ...` in a subprocess or its main()), dask (needs dask),
needs_data (reads ../shared/data). E.g. `pytest -m "not slow and not cli"` for a quick run.

Hypothesis: the profile is chosen by the environment variable HYPOTHESIS_PROFILE, default "ci":
derandomized (the same examples on every run and machine: no flaky failures), no deadline (the
machine is shared), no example database. "dev": random examples, as many as a test's own
@settings asks for. Tests that set max_examples in their own @settings keep them (fuzz 40,
properties 100); the profile's max_examples (100) applies to the others.
"""

import os
import signal

import pytest
from hypothesis import HealthCheck, settings

pytest.register_assert_rewrite("support")  # the helpers' asserts (support/grids.py) explain failures

from support.data import SHARED_DATA, missing  # noqa: E402

# Ctrl-C: the tests that send SIGINT (to this process, or to a seaway they start) need Python's
# own handler. A shell that starts the suite as a background job hands it SIGINT ignored, Python
# then keeps it ignored and its children inherit that: those tests hung or routed on.
if signal.getsignal(signal.SIGINT) is signal.SIG_IGN:
    signal.signal(signal.SIGINT, signal.default_int_handler)

settings.register_profile(
    "ci",
    derandomize=True,
    deadline=None,
    database=None,
    max_examples=100,
    print_blob=True,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile("dev", deadline=None, max_examples=100)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))


def pytest_report_header(config):
    return [
        f"hypothesis profile: {settings._current_profile}",
        f"shared data: {SHARED_DATA}" + ("" if SHARED_DATA.is_dir() else " (absent)"),
    ]


def pytest_runtest_setup(item):
    for mark in item.iter_markers("needs_data"):
        why = missing(*mark.args)
        if why:
            pytest.skip(why)


@pytest.fixture(scope="session")
def shared_data():
    """The real data folder (pathlib.Path); skips the test when it is absent."""
    why = missing()
    if why:
        pytest.skip(why)
    return SHARED_DATA
