"""A batch's journal: route_voyages appends each row to a CSV file as soon as it is routed, and
a batch started again with the same journal routes only the rows it does not hold yet — a
study of tens of thousands of voyages survives a crash, a killed job or Ctrl-C."""

from __future__ import annotations

import csv
import io
import os
import threading
from collections.abc import Sequence
from typing import Any

import numpy as np

from ..errors import SeawayError

#: Columns read back as dates, as numbers; the others are text.
DATES = ("departure", "arrival")
TEXT = ("vessel", "voyage", "status", "cause", "error")


def row_key(vessel: Any, voyage: Any, departure: Any) -> tuple[str, str, str]:
    """The identity of a row: its vessel, voyage and departure as the journal writes them."""
    return str(vessel), str(voyage), _text(departure)


class Journal:
    """The CSV file `path` of a batch whose rows have `columns`; `done` maps each row it already
    holds (row_key) to that row, read back with dates as numpy.datetime64 and numbers as floats.
    A last line cut short (the process was killed while writing it) is dropped and said."""

    def __init__(self, path: str | os.PathLike[str], columns: Sequence[str], say=print) -> None:
        self.path, self.columns, self.lock = os.fspath(path), list(columns), threading.Lock()
        self.done: dict[tuple[str, str, str], dict[str, Any]] = {}
        if not os.path.exists(self.path) or os.path.getsize(self.path) == 0:
            with open(self.path, "w", newline="") as f:
                csv.writer(f).writerow(self.columns)
            return
        with open(self.path, "rb") as f:
            data = f.read()
        if not data.endswith(b"\n"):
            cut = data.rfind(b"\n") + 1
            with open(self.path, "r+b") as f:
                f.truncate(cut)
            say(f"{self.path}: its last line was cut short ({len(data) - cut} bytes) and is routed again")
            data = data[:cut]
        rows = csv.reader(io.StringIO(data.decode()))
        header = next(rows, [])
        if header != self.columns:
            raise SeawayError(
                f"{self.path} is not a journal of this batch (its columns are {header[:4]}...): "
                "give a new file, or the journal this batch wrote"
            )
        for values in rows:
            row = {c: _read(c, v) for c, v in zip(self.columns, values)}
            self.done[row_key(row["vessel"], row["voyage"], row["departure"])] = row

    def write(self, row: dict[str, Any]) -> None:
        """Append `row` as one line, written and flushed at once (threads share the journal)."""
        out = io.StringIO()
        csv.writer(out).writerow([_text(row.get(c)) for c in self.columns])
        with self.lock, open(self.path, "a", newline="") as f:
            f.write(out.getvalue())
            f.flush()


def _text(value: Any) -> str:
    if value is None or (isinstance(value, float) and np.isnan(value)):
        return ""
    if isinstance(value, np.datetime64):
        return "" if np.isnat(value) else str(value)
    if hasattr(value, "isoformat") and not isinstance(value, str):  # pandas.Timestamp, datetime
        return "" if value != value else value.isoformat()
    return repr(value) if isinstance(value, float) else str(value)


def _read(column: str, value: str) -> Any:
    if column in TEXT:
        return value
    if column in DATES:
        return np.datetime64(value) if value else None
    return float(value) if value else float("nan")
