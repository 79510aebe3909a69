"""Test helpers, imported one way: `from support.reference import RefGraph`, `from support import
panarctic`. pyproject's `[tool.pytest.ini_options] pythonpath = ["tests"]` puts tests/ on sys.path
for every run (`pytest` or `python -m pytest` from the root, `.ci/sanitize`, `pytest benchmarks/`).

- data.py          SHARED_DATA: the real data folder ../shared/data (see tests/conftest.py)
- reference.py     an independent pure-Python search (RefGraph), haversine, season references
- reference_legs.py, reference_turns.py  numpy references for leg tables and turn penalties
- panarctic.py     a synthetic pan-Arctic SIGRID-3 chart
- netcdf.py        small NetCDF inputs for the bad-file tests
- webmap_check.js  runs a saved web map in jsdom (tests/output/test_webmap.py)
"""
