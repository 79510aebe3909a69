"""python -m seaway: the command line (seaway.cli)."""

from .cli import entry, main  # noqa: F401 - main: for callers of the old entry point

if __name__ == "__main__":
    entry()
