"""The judge of the hostile-input campaign (issue 27; engine/test_hostile_arrays.py and
cli/test_hostile_files.py): a call on bad input must answer, or raise a seaway.SeawayError (a
ValueError; SeawayTypeError is a TypeError too) whose message is one line and whose traceback
ends in seaway's own code, not in numpy, GDAL, GEOS, netCDF4 or pybind11's argument matching."""

from __future__ import annotations

import contextlib
import io
import os
import traceback

import seaway

PACKAGE = os.path.dirname(seaway.__file__) + os.sep
#: Messages that are another library's words passed through (pybind11's argument matching,
#: numpy's allocator, GEOS, a traceback printed into a message).
FOREIGN = ("incompatible function arguments", "Unable to allocate", "GEOSException", "Traceback (most recent")
#: How many rounds the campaigns run (SEAWAY_HOSTILE_ROUNDS=N for a longer run; seeds 0..N-1).
ROUNDS = int(os.environ.get("SEAWAY_HOSTILE_ROUNDS", "1"))


class Judge:
    """Collects what went wrong over a campaign; `verdict()` fails the test with all of it."""

    def __init__(self):
        self.faults: list[str] = []
        self.answered = self.refused = 0

    def __call__(self, label, fn):
        """fn() -> its value, or None when it raised a clean error; faults are recorded."""
        try:
            value = fn()
        except (ValueError, TypeError) as exc:
            self.refused += 1
            fault = unclean(exc)
            if fault:
                self.faults.append(f"{label}: {fault}")
            return None
        except Exception as exc:  # noqa: BLE001 - anything else is a fault of the package
            tb = traceback.extract_tb(exc.__traceback__)
            where = (
                " <- ".join(f"{os.path.basename(f.filename)}:{f.lineno}" for f in reversed(tb[-5:])) or "?"
            )
            self.faults.append(f"{label}: {type(exc).__name__} at {where}: {one_line(str(exc))}")
            return None
        self.answered += 1
        return value

    def fault(self, label, what):
        self.faults.append(f"{label}: {what}")

    def verdict(self, at_least=1):
        assert not self.faults, f"{len(self.faults)} faults:\n" + "\n".join(self.faults[:40])
        assert self.refused >= at_least, "the campaign refused nothing: its inputs are not hostile"


def unclean(exc) -> str | None:
    """What is wrong with an error raised on bad input, or None."""
    message = str(exc)
    if not message.strip():
        return f"{type(exc).__name__} without a message"
    if "\n" in message.strip():
        return f"{type(exc).__name__} of {message.count(chr(10)) + 1} lines: {one_line(message)}"
    if not isinstance(exc, seaway.SeawayError):
        return f"{type(exc).__name__}, not a seaway.SeawayError: {one_line(message)}"
    if any(f in message for f in FOREIGN):
        return f"another library's words: {one_line(message)}"
    tb = traceback.extract_tb(exc.__traceback__)
    if tb and not tb[-1].filename.startswith(PACKAGE):
        return f"raised in {tb[-1].filename}:{tb[-1].lineno}: {type(exc).__name__}: {one_line(message)}"
    return None


def one_line(text, n=160):
    text = " ".join(str(text).split())
    return text if len(text) <= n else text[: n - 3] + "..."


def run_cli(judge, label, argv):
    """seaway.cli.main(argv): status 0, or 1 with one line `seaway CMD: error: ...` last on
    stderr, or argparse's usage error (SystemExit 2); anything else is a fault."""
    from seaway.cli import main

    err = io.StringIO()
    try:
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
            status = judge(label, lambda: main(argv))
    except SystemExit as exc:
        if exc.code != 2:
            judge.fault(label, f"SystemExit({exc.code!r})")
        judge.refused += 1
        return 2
    text = err.getvalue()
    if status is None:  # main() raised a ValueError/TypeError instead of saying it: judged above
        return None
    if status == 1:
        judge.refused += 1
        judge.answered -= 1
        last = text.strip().splitlines()[-1] if text.strip() else ""
        if not last.startswith(f"seaway {argv[0]}: error: ") or "Traceback" in text:
            judge.fault(label, f"status 1 without a one-line error: {one_line(text[-300:])}")
        elif any(f in last for f in FOREIGN):
            judge.fault(label, f"another library's words: {one_line(last)}")
    elif status != 0:
        judge.fault(label, f"status {status}: {one_line(text[-300:])}")
    if "Traceback" in text or "Warning:" in text:
        judge.fault(label, f"a traceback or warning on stderr: {one_line(text[-300:])}")
    return status
