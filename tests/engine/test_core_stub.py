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
