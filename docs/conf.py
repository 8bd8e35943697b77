"""Sphinx configuration of the documentation site (``make docs``; docs/_build/html).

The API reference is generated from the numpydoc docstrings (autosummary over every
public module), the user guide is the Markdown pages of this folder (MyST), and the
gallery runs the scripts of ``examples/`` (sphinx-gallery) and keeps their figures.
"""

from __future__ import annotations

import os
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

from ballscrew import __version__  # noqa: E402 - after the backend is chosen

ROOT = Path(__file__).resolve().parents[1]

project = "ballscrew"
author = "ballscrew developers"
copyright = "2026, ballscrew developers"  # noqa: A001 - Sphinx's name
release = version = __version__

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "sphinx-mathjax-offline",  # MathJax copied into _static: equations render offline
    "sphinx.ext.viewcode",
    "numpydoc",
    "myst_parser",
    "sphinx_gallery.gen_gallery",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "gallery/*.ipynb", "gallery/*.py", "gallery/*.zip"]
templates_path = ["_templates"]

# The API reference: a page per module, its members (its __all__) on it.
autosummary_generate = True
autosummary_imported_members = False
autodoc_default_options = {"members": True, "undoc-members": True, "show-inheritance": True}
autodoc_typehints = "none"  # numpydoc's Parameters give the types and the units
numpydoc_show_class_members = False
numpydoc_validation_checks: set[str] = set()
# The docstrings list their sources under References without citing each in the text.
suppress_warnings = ["ref.citation"]

# MathJax from the site itself (sphinx-mathjax-offline copies it from its wheel into
# _static/mathjax), not from a CDN: machine-tool shops often read the docs offline.
mathjax_path = "mathjax/tex-chtml.js"

# The Markdown pages: GitHub's heading anchors, $...$ and $$...$$ maths.
myst_heading_anchors = 4
myst_enable_extensions = ["dollarmath", "amsmath"]

sphinx_gallery_conf = {
    "examples_dirs": str(ROOT / "examples"),
    "gallery_dirs": "gallery",
    "filename_pattern": r"/plot_",  # only the plot_*.py scripts run when the docs build
    "download_all_examples": False,
    "abort_on_example_error": True,
    "remove_config_comments": True,
}

html_theme = "pydata_sphinx_theme"
html_title = f"ballscrew {__version__}"
html_theme_options = {
    "navigation_depth": 2,
    "show_toc_level": 2,
    "header_links_before_dropdown": 3,
}
os.environ.setdefault("MPLBACKEND", "Agg")  # the gallery's scripts draw off screen
