"""route_voyages(journal=...): rows appended as they are routed; a batch started again reads
back what the journal holds and routes only the rest, with the same table."""

import numpy as np
import pandas as pd
import pytest

import seaway
from seaway.fleet import daily, route_voyages
from support.seasons import DAY0, retreating_edge

VOYAGES = {"sea": ((71.0, 70.0), (76.0, 74.0)), "land": ((74.0, 61.0), (76.0, 74.0))}
DAYS = daily(DAY0, DAY0 + np.timedelta64(2, "D"))


@pytest.fixture(scope="module")
def season(tmp_path_factory):
    path = tmp_path_factory.mktemp("journal") / "week.nc"
    retreating_edge(days=4).to_netcdf(path)
    return seaway.open_season(str(path))


def _batch(season, **kw):
    return route_voyages(season, VOYAGES, vessels=("Arc4", "Arc7"), departures=DAYS, **kw)


def test_a_stopped_batch_goes_on_where_it_was(season, tmp_path, monkeypatch, capsys):
    fresh = _batch(season, threads=1)
    path = tmp_path / "study.csv"
    whole = _batch(season, threads=2, journal=path)
    pd.testing.assert_frame_equal(whole, fresh)
    lines = path.read_text().splitlines()
    assert len(lines) == 1 + 12 and lines[0].startswith("vessel,voyage,departure,start_lat")
    # The job was killed while writing its fourth row: three whole rows and part of a line.
    path.write_text("\n".join(lines[:4]) + "\n" + lines[4][:25])
    calls = []  # the ends each search of the batch routes to (OpenSeason.routes)
    routes = type(season).routes
    monkeypatch.setattr(
        type(season), "routes", lambda self, a, ends, **k: calls.extend(ends) or routes(self, a, ends, **k)
    )
    again = _batch(season, threads=2, journal=path)
    assert len(calls) == 12 - 3  # only the rows the journal did not hold
    pd.testing.assert_frame_equal(again, fresh)  # hours, arrivals, causes read back exactly
    err = capsys.readouterr().err
    assert "its last line was cut short (25 bytes)" in err and "3 of 12 rows read back, 9 to route" in err
    assert len(path.read_text().splitlines()) == 1 + 12
    calls.clear()
    pd.testing.assert_frame_equal(_batch(season, journal=path), fresh)
    assert calls == []  # all read back


def test_a_file_that_is_not_a_journal_is_refused(season, tmp_path):
    path = tmp_path / "other.csv"
    path.write_text("a,b,c\n1,2,3\n")
    with pytest.raises(seaway.SeawayError, match="not a journal of this batch"):
        _batch(season, journal=path)
    assert path.read_text() == "a,b,c\n1,2,3\n"  # left as it was
