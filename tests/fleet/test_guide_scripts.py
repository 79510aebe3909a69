"""The many-routes guide's Dask scripts run as written (python script.py, a LocalCluster of
worker processes that import the script again), give their tables, and shut down without a
traceback on stderr."""

import re
import subprocess
import sys
from pathlib import Path

import pytest

from support.seasons import retreating_edge

GUIDE = Path(__file__).resolve().parents[2] / "docs" / "user" / "many-routes.md"


def _scripts():
    blocks = re.findall(r"```python\n(.*?)```", GUIDE.read_text(), flags=re.S)
    return [b for b in blocks if 'if __name__ == "__main__"' in b]


def test_the_guide_has_its_two_scripts():
    scripts = _scripts()
    assert len(scripts) == 2 and all("def main():" in s for s in scripts)


@pytest.mark.dask
@pytest.mark.parametrize("which", [0, 1])
def test_a_guide_script_runs_as_written(which, tmp_path):
    pytest.importorskip("dask.distributed")
    retreating_edge(days=4).to_netcdf(tmp_path / "season.nc")
    script = tmp_path / "fleet.py"
    script.write_text(_scripts()[which])
    done = subprocess.run(
        [sys.executable, str(script)], cwd=tmp_path, capture_output=True, text=True, timeout=600
    )
    assert done.returncode == 0, done.stderr[-3000:]
    assert "Traceback" not in done.stderr and "CommClosedError" not in done.stderr, done.stderr[-3000:]
    if which == 0:
        assert "Arc4" in done.stdout and "Arc7" in done.stdout
    else:  # two batches on one client: Arc4's voyages closed by ice, Arc7's routed
        assert done.stdout.count("Ob–Vilkitsky") == 6 and "no route" in done.stdout and " ok" in done.stdout
