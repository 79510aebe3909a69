"""Where the real data lives: ../shared/data next to the repository (the repository's parent
folder holds shared/data), or the folder named by SEAWAY_SHARED_DATA. The one recipe for it; use
it through tests/conftest.py (the `needs_data` marker and the `shared_data` fixture)."""

import os
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]  # tests/support/data.py -> the repository
SHARED_DATA = Path(os.environ.get("SEAWAY_SHARED_DATA") or ROOT.parent / "shared" / "data")


def missing(*parts):
    """Why a test needing SHARED_DATA / parts cannot run, or "" when it is there."""
    path = SHARED_DATA.joinpath(*parts)
    if not SHARED_DATA.is_dir():
        return f"the real data folder {SHARED_DATA} (../shared/data) is absent"
    return "" if path.exists() else f"{path} is absent"
