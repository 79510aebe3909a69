"""Requests too large for the machine are refused before anything is allocated, with the figure,
the limit and the fix (issue 27): grids of SIGRID-3 charts (--grid and the default route grid),
seasons, projected forecasts resampled onto --grid, the samples' sizes, the engine's search and
landmarks. SEAWAY_MEMORY_LIMIT sets the limit here, so the figures do not depend on the machine;
test_memory_refusal.py runs the issue's reproducers under a real address-space limit."""

import os

import numpy as np
import pytest

import seaway
from seaway.base import memory
from seaway.ice.grids import CHART, latlon_grid
from seaway.ice.routegrid import route_grid
from seaway.samples import kara_sea, kara_season, synthetic_sea

DMI = ("ice_charts_sigrid3", "dmi_greenland")
STEM = "201304100920_CapeFarewell_RIC"


@pytest.fixture
def small(monkeypatch):
    monkeypatch.setenv(memory.ENV, "64M")  # 67,108,864 bytes


def test_the_limit_is_a_share_of_the_machine_or_the_override(monkeypatch):
    monkeypatch.delenv(memory.ENV, raising=False)
    physical = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    cap, why = memory.limit()
    assert 0 < cap <= 0.75 * physical and ("machine" in why or "limit" in why)
    for text, value in [
        ("8G", 8 * 2**30),
        ("500M", 500 * 2**20),
        ("1.5GiB", int(1.5 * 2**30)),
        ("123456", 123456),
    ]:
        monkeypatch.setenv(memory.ENV, text)
        assert memory.limit() == (value, f"SEAWAY_MEMORY_LIMIT={text}")
    monkeypatch.setenv(memory.ENV, "lots")
    with pytest.raises(
        ValueError, match="SEAWAY_MEMORY_LIMIT must be a number of bytes such as 8G or 500M, got 'lots'"
    ):
        memory.limit()


def test_a_grid_too_fine_is_refused_naming_a_resolution_that_fits(small):
    with pytest.raises(seaway.ChartError) as err:
        latlon_grid(56, 64, -56, -37, 0.001)  # the issue's --grid=56,64,-56,-37,0.001
    assert str(err.value) == (
        "a chart on a grid of 8,000 x 19,000 pixels (152,000,000) needs about 19.3 GiB, more than "
        "the 64 MiB seaway may take (SEAWAY_MEMORY_LIMIT=64M); give a coarser grid (e.g. a "
        "resolution of 0.02 deg: 400 x 950 pixels) or a smaller box"
    )
    assert 400 * 950 * CHART <= 64 * 2**20 < 380 * 1000 * CHART * 2  # the suggestion fits
    assert latlon_grid(56, 64, -56, -37, 0.02).shape == (400, 950)
    with pytest.raises(
        seaway.ChartError, match=r"80,000 x 190,000 pixels \(15,200,000,000\) needs about 1\.9 TiB"
    ):
        latlon_grid(56, 64, -56, -37, 0.0001)  # 56.6 GiB for one int32 layer: numpy's traceback
    with pytest.raises(
        seaway.ChartError, match=r"latitude: resolution 4\.94066e-324 is too fine for an extent of 8"
    ):
        latlon_grid(56, 64, -56, -37, 5e-324)


def test_the_default_route_grid_is_coarsened_to_fit_and_says_so(monkeypatch):
    monkeypatch.setenv(memory.ENV, "8M")  # 61,680 pixels of a chart read and routed
    grid, note = route_grid((70.3, 58.5), (77.7, 104.0))  # 290 x 434 = 125,860 pixels otherwise
    rows, cols = grid.shape
    assert rows * cols * CHART <= 8 * 2**20
    assert note.endswith("coarsened to fit in memory (55,512 pixels at most)")
    unconstrained, note = route_grid((59.5, -44.0), (60.5, -48.0))  # small already: as before
    assert "coarsened" not in note and unconstrained.shape == (128, 150)


def test_samples_too_large_are_refused_naming_a_shape_that_fits(small):
    with pytest.raises(seaway.SeawayError) as err:
        kara_sea((100_000, 100_000))
    assert str(err.value) == (
        "the synthetic Kara Sea of 100,000 x 100,000 pixels (10,000,000,000) needs about 1.8 TiB, "
        "more than the 64 MiB seaway may take (SEAWAY_MEMORY_LIMIT=64M); give a smaller shape, "
        "e.g. (567, 567)"
    )
    assert 567 * 567 * (memory.KARA + memory.ROUTE) <= 64 * 2**20  # the shape named fits
    with pytest.raises(seaway.SeawayError, match=r"^400 days of the synthetic Kara Sea .*; give fewer days"):
        kara_season(days=400)
    with pytest.raises(
        seaway.SeawayError, match=r"^the synthetic sea of 3,000 x 3,000 pixels .* e\.g\. \(886, 886\)$"
    ):
        synthetic_sea((3000, 3000))


def test_the_engine_refuses_a_search_or_landmarks_the_machine_cannot_hold(monkeypatch):
    cost = np.ones((1000, 1000), np.float32)
    monkeypatch.setenv(memory.ENV, "5M")
    with pytest.raises(seaway.SeawayError) as err:
        seaway.route(cost, (0, 0), (999, 999))
    assert str(err.value) == (
        "the search on a chart of 1,000 x 1,000 pixels (1,000,000) needs about 10 MiB, more than "
        "the 5 MiB seaway may take (SEAWAY_MEMORY_LIMIT=5M); route on a coarser chart (e.g. "
        "cost[::2, ::2]) or on a part of it"
    )
    # a broadcast view stands for far more memory than it holds: its copy is counted
    monkeypatch.setenv(memory.ENV, "16G")
    with pytest.raises(
        seaway.SeawayError,
        match=r"^the search on a chart copied to C order of 60,000 x 60,000 pixels .* 60\.3 GiB",
    ):
        seaway.route(np.broadcast_to(1.0, (60_000, 60_000)), (0, 0), (1, 1))
    monkeypatch.setenv(memory.ENV, "15M")
    with pytest.raises(
        seaway.SeawayError, match=r"^the search on a chart converted to float64 of 1,000 x 1,000 .* 17 MiB"
    ):
        seaway.prepare(cost.astype(np.uint8))
    monkeypatch.setenv(memory.ENV, "20M")
    chart = seaway.prepare(cost)
    with pytest.raises(
        seaway.SeawayError, match=r"^8 landmark tables of 1,000 x 1,000 pixels .* needs about 31 MiB"
    ):
        chart.prepare_landmarks(8)
    assert chart.prepare_landmarks(2)["count"] == 2


@pytest.mark.needs_data(*DMI)
def test_open_chart_and_seasons_on_a_grid_too_fine_are_refused(shared_data, small):
    pytest.importorskip("pyogrio")
    shp = shared_data.joinpath(*DMI, STEM + ".shp")
    with pytest.raises(seaway.ChartError, match=r"^a chart on a grid of 8,000 x 19,000 pixels .* 0\.02 deg"):
        seaway.open_chart(shp, grid=(56, 64, -56, -37, 0.001))
    with pytest.raises(seaway.ChartError, match=r"^a season of 2 charts on a grid of 800 x 1,900 pixels"):
        seaway.open_season({"2013-04-10": shp, "2013-04-12": shp}, grid=(56, 64, -56, -37, 0.01))


@pytest.mark.needs_data("ocean_model")
def test_a_projected_forecast_resampled_onto_a_grid_too_fine_is_refused(shared_data, small):
    fc = seaway.open_forecast(shared_data / "ocean_model" / "metno_ROMS_Arctic20_1to5Feb_2016.nc")
    with pytest.raises(seaway.SeawayError) as err:
        fc.route((70.5, 20.0), (76.0, 45.0), depart="2016-02-01T12:00", grid=(68, 80, 10, 55, 0.01))
    assert str(err.value).startswith(
        "metno_ROMS_Arctic20_1to5Feb_2016.nc (20 fields and frames) resampled onto a grid of 1,200 x "
        "4,500 pixels (5,400,000) needs about 4.5 GiB"
    )
