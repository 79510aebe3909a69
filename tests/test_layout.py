"""The layout's limits, checked on the source tree (docs/dev/architecture.md): Python modules of
at most 300 lines, C++ headers of at most 200, at most 15 modules at the top of src/seaway, and
function-level imports between seaway modules only those the import contract names (the
contract, lint-imports in CI, checks the module-level ones)."""

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SRC = ROOT / "src" / "seaway"
pytestmark = pytest.mark.skipif(not SRC.is_dir(), reason="needs the source tree (a clone)")


def _lines(path):
    return len(path.read_text(encoding="utf-8").splitlines())


def test_python_modules_are_at_most_300_lines():
    long = {str(p.relative_to(SRC)): _lines(p) for p in SRC.rglob("*.py") if _lines(p) > 300}
    assert long == {}


def test_cpp_headers_are_at_most_200_lines():
    long = {p.name: _lines(p) for p in (ROOT / "cpp").rglob("*.hpp") if _lines(p) > 200}
    assert long == {}


def test_at_most_15_modules_at_the_top_of_the_package():
    # Modules beside the layers' packages (base, chart, engine, ...): the public entry points.
    top = sorted(p.name for p in SRC.glob("*.py") if p.name != "__init__.py")
    assert 0 < len(top) <= 15, top


def _module(path):
    parts = list(path.relative_to(SRC.parent).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts), path.name == "__init__.py"


def _targets(node, module, is_package):
    """The seaway modules a function-level import names ("from . import x": the module x)."""
    if isinstance(node, ast.Import):
        return [a.name for a in node.names if a.name.split(".")[0] == "seaway"]
    if node.level == 0:
        base = node.module or ""
        if base.split(".")[0] != "seaway":
            return []
    else:
        parts = module.split(".")
        parts = parts[: len(parts) - node.level + (1 if is_package else 0)]
        base = ".".join(parts + ([node.module] if node.module else []))
    subs = [f"{base}.{a.name}" for a in node.names]
    path = SRC.parent.joinpath(*base.split("."))
    named = [
        m for m, a in zip(subs, node.names) if (path / f"{a.name}.py").exists() or (path / a.name).is_dir()
    ]
    return named or [base]


def _function_level_imports():
    found = set()
    for path in SRC.rglob("*.py"):
        module, is_package = _module(path)
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for fn in ast.walk(tree):
            if not isinstance(fn, (ast.FunctionDef, ast.AsyncFunctionDef)):
                continue
            for node in ast.walk(fn):
                if isinstance(node, (ast.Import, ast.ImportFrom)):
                    for target in _targets(node, module, is_package):
                        if target != "seaway" and not target.startswith("seaway._core"):
                            found.add((module, target))
    return found


def test_function_level_imports_are_the_few_the_contract_names():
    tomllib = pytest.importorskip("tomllib")  # Python 3.11 on
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    (contract,) = config["tool"]["importlinter"]["contracts"]
    named = {tuple(s.split(" -> ")) for s in contract.get("ignore_imports", [])}
    found = _function_level_imports()
    # Each import is named (an imported name may be a module below the named one's package).
    unnamed = {
        (a, b)
        for a, b in found
        if not any(a == na and (b == nb or b.startswith(nb + ".")) for na, nb in named)
    }
    assert unnamed == set()
    assert found == set()  # none: the contract names no exception


def test_route_conveniences_come_from_the_layers_above():
    """Route.smoothed(), .explore() and .to_html() run the functions of seaway.smoothing and
    seaway.output.webmap, put in place by those modules (the result layer imports nothing above)."""
    import seaway
    from seaway.output.webmap import explore, to_html
    from seaway.result.route import ABOVE

    assert ABOVE == {"smoothed": seaway.smooth, "explore": explore, "to_html": to_html}
