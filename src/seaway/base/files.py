"""File helpers: atomic writes (write_atomically, replace_atomically: never a half-written
file; write_all: several files all or nothing) and output paths checked before any work
(check_output). The readers of input files (check_netcdf, open_netcdf, read_geotiff) live in
seaway.base.readers and are importable from here too."""

from __future__ import annotations

import os
import tempfile
from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING

from ..errors import SeawayError
from .readers import check_netcdf as check_netcdf
from .readers import open_netcdf as open_netcdf
from .readers import read_geotiff as read_geotiff

if TYPE_CHECKING:
    #: A file name as the API takes it.
    PathLike = str | os.PathLike[str]


def write_atomically(path: PathLike, text: str) -> None:
    """Write `text` to a temporary file beside `path`, then rename it over `path`."""
    write_all([(path, text)])


def replace_atomically(path: PathLike, write: Callable[[int, str], None], suffix: str) -> None:
    """write(fd, temporary path) fills a temporary file beside `path`, which is then given the
    permissions of a newly created file (mkstemp's are 0600: others could not read the
    route) and renamed over `path`; on any error the temporary file is removed, and an OSError
    names `path` (never the temporary file)."""
    target = os.path.abspath(os.fspath(path))
    tmp = _temporary(target, suffix)
    try:
        try:
            write(os.open(tmp, os.O_WRONLY), tmp)
        except OSError as exc:
            raise _named(exc, path) from None
        _publish([(tmp, target, path)])
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def check_output(path: PathLike, formats: dict[str, str], option: str = "--out") -> str:
    """The format of an output file named by its extension (`formats`: {".ext": name}), checked
    before any work is done: ValueError naming the fix when the extension is unknown, the path
    is a directory, its directory is missing or not writable, or the file exists read-only."""
    path = os.fspath(path)
    if os.path.isdir(path):
        raise SeawayError(f"{option} {path} is a directory; give a file name inside it")
    ext = os.path.splitext(path)[1].lower()
    if ext not in formats:
        raise SeawayError(
            f"{option} {path}: cannot tell the format from the extension "
            f"{ext or '(none)'!r}; use one of {', '.join(sorted(formats))}"
        )
    folder = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(folder):
        raise SeawayError(f"{option} {path}: the directory {folder} does not exist; create it first")
    if not os.access(folder, os.W_OK | os.X_OK):
        raise SeawayError(f"{option} {path}: the directory {folder} is not writable; choose another")
    if os.path.exists(path) and not os.access(path, os.W_OK):
        raise SeawayError(f"{option} {path} exists and is read-only; remove it or choose another name")
    return formats[ext]


def write_all(files: Iterable[tuple[PathLike, str | bytes]]) -> None:
    """Write several files all or nothing: `files` is [(path, str or bytes), ...]. Each goes to a
    temporary file beside its target; only when every one is written are they renamed over
    their targets (with a new file's usual permissions). On any failure every temporary file is
    removed, no target is touched, and the OSError names the target, never a temporary file."""
    staged: list[tuple[str, str, PathLike]] = []
    try:
        for path, data in files:
            target = os.path.abspath(os.fspath(path))
            tmp = _temporary(target, ".tmp")
            staged.append((tmp, target, path))
            try:
                fd = os.open(tmp, os.O_WRONLY | os.O_TRUNC)
                if isinstance(data, (bytes, bytearray)):
                    with os.fdopen(fd, "wb") as f:
                        f.write(data)
                else:
                    with os.fdopen(fd, "w", encoding="utf-8", newline="") as f:
                        f.write(data)
            except OSError as exc:
                raise _named(exc, path) from None
        for _, target, path in staged:  # what would make a rename fail, before the first one
            if os.path.isdir(target):
                raise IsADirectoryError(21, f"{os.fspath(path)}: cannot write it (a directory)")
        _publish(staged)
    finally:
        for tmp, _, _ in staged:
            if os.path.exists(tmp):
                os.unlink(tmp)


def _temporary(target: str, suffix: str) -> str:
    """A new empty temporary file beside `target`; OSError naming `target` if it cannot be made."""
    try:
        fd, tmp = tempfile.mkstemp(dir=os.path.dirname(target), prefix=".seaway-", suffix=suffix)
    except OSError as exc:
        raise _named(exc, target) from None
    os.close(fd)
    return tmp


def _publish(staged: Iterable[tuple[str, str, PathLike]]) -> None:
    """Give each staged (temporary, target, name) file a new file's permissions, then rename it
    over its target."""
    umask = os.umask(0)
    os.umask(umask)
    for tmp, target, name in staged:
        try:
            os.chmod(tmp, 0o666 & ~umask)
            os.replace(tmp, target)
        except OSError as exc:
            raise _named(exc, name) from None


def _named(exc: OSError, path: PathLike) -> OSError:
    """The OSError for `path`, with the system's reason but not the temporary file's name."""
    reason = exc.strerror or str(exc).split(": '")[0]
    text = f"{os.fspath(path)}: cannot write it ({reason})"
    return type(exc)(exc.errno, text) if exc.errno is not None else type(exc)(text)
