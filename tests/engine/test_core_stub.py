"""src/seaway/_core.pyi is hand-written: it must name exactly what the compiled module has, and
each class in it the methods the class has."""

import ast
from pathlib import Path

from seaway import _core

STUB = Path(__file__).resolve().parents[2] / "src" / "seaway" / "_core.pyi"


def _stub():
    tree = ast.parse(STUB.read_text())
    top, members, aliases = set(), {}, set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            top.add(node.name)
        if isinstance(node, ast.ClassDef):
            members[node.name] = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
        if isinstance(node, (ast.Assign, ast.AnnAssign)):
            for t in node.targets if isinstance(node, ast.Assign) else [node.target]:
                if isinstance(t, ast.Name):
                    (aliases if t.id[:1].isupper() else top).add(t.id)  # Model = A | B: typing only
    return top - aliases, members


def test_the_stub_names_what_the_compiled_module_has():
    top, _ = _stub()
    compiled = {n for n in dir(_core) if not n.startswith("_")}
    assert sorted(compiled - top) == [], "in _core but missing from _core.pyi"
    assert sorted(top - compiled) == [], "in _core.pyi but not in _core"


def test_the_stub_classes_have_their_methods():
    _, members = _stub()
    for name, methods in members.items():
        cls = getattr(_core, name)
        missing = sorted(m for m in methods if not m.startswith("__") and not hasattr(cls, m))
        assert missing == [], f"_core.{name} lacks {missing} named in _core.pyi"


def test_the_build_uses_the_page_strategy_asked():
    """cpp/seaway/pages.hpp: Linux's mmap/madvise by default there, the portable calloc build
    elsewhere or when forced (.ci/portable sets SEAWAY_EXPECT_PAGES to check it runs that one)."""
    import os
    import sys

    expect = os.environ.get("SEAWAY_EXPECT_PAGES")
    if expect is None:
        expect = "linux-madvise" if sys.platform.startswith("linux") else "portable-calloc"
    assert _core.page_strategy == expect


def test_released_labels_read_as_unreached():
    """A prepared chart gives its labels' pages back between big searches (LazyLabels.release):
    the next searches, on either page strategy, find the same costs as fresh ones."""
    import numpy as np

    import seaway

    rng = np.random.default_rng(5)
    cost = rng.uniform(1, 9, (300, 400))
    chart = seaway.prepare(cost)
    first = [chart.route((0, 0), (299, 399), method=m).cost for m in ("dijkstra", "astar", "bidirectional")]
    again = [chart.route((5, 7), (290, 380), method="dijkstra").cost for _ in range(3)]
    fresh = seaway.route(cost, (5, 7), (290, 380), method="dijkstra").cost
    assert np.allclose(first, first[0], rtol=1e-12) and np.allclose(again, fresh, rtol=1e-12)
