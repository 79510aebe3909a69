"""Sphinx configuration of seaway's documentation (MyST Markdown pages, API by autosummary)."""

import os
import sys

import seaway

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "_ext"))

project = "seaway"
author = "seaway developers"
copyright = "2026, seaway developers"
release = seaway.__version__
version = ".".join(release.split(".")[:2])

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.napoleon",     # the docstrings are plain prose with a few numpydoc sections
    "sphinx.ext.doctest",
    "sphinx.ext.mathjax",
    "sphinxarg.ext",
    "plain_docstrings",       # docs/_ext: the docstrings' plain "name: text" convention
]

source_suffix = {".md": "markdown", ".rst": "restructuredtext"}
myst_enable_extensions = ["colon_fence", "deflist", "dollarmath"]
myst_heading_anchors = 3
exclude_patterns = ["_build"]
templates_path = ["_templates"]

# API reference: one page per public module (docs/api/index.md lists them).
autosummary_generate = True
# Public names are those in a module's __all__ (re-export modules list what they re-export).
autosummary_imported_members = False
autosummary_ignore_module_all = False
autodoc_member_order = "bysource"
# Module constants are shown with their values, except these long tables (described in words).
autosummary_context = {"long_values": ["CLASSES", "ICE_IMPACT"]}
autodoc_typehints = "signature"
napoleon_google_docstring = False
napoleon_numpy_docstring = True


# Doctests (make doctest: sphinx-build -b doctest docs DIR) run against the installed package.
doctest_global_setup = "import numpy as np\nimport seaway"

html_theme = "furo"
html_title = f"seaway {release}"
html_static_path = []
