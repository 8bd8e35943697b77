"""Sphinx configuration of the documentation site (``make docs``; docs/_build/html).

The API reference is generated from the numpydoc docstrings (autosummary over every
public module), the user guide is the Markdown pages of this folder (MyST), and the
gallery runs the scripts of ``examples/`` (sphinx-gallery) and keeps their figures; the
worked notebooks of ``notebooks/`` run at each build (myst-nb).
"""

from __future__ import annotations

import os
import subprocess
import sys
import types
from pathlib import Path
from typing import Any

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
    "myst_nb",  # MyST Markdown pages and the notebooks of notebooks/, run at each build
    "sphinx_gallery.gen_gallery",
]

source_suffix = {".rst": "restructuredtext", ".md": "myst-nb", ".ipynb": "myst-nb"}
root_doc = "index"
exclude_patterns = [
    "_build", "gallery/*.ipynb", "gallery/*.py", "gallery/*.zip", "**.ipynb_checkpoints",
]
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

# The notebooks are stored without outputs and run at every build (in their folder); an
# error in a cell fails the build.
nb_execution_mode = "force"
nb_execution_timeout = 120
nb_execution_raise_on_error = True
nb_execution_show_tb = True

sphinx_gallery_conf = {
    "examples_dirs": str(ROOT / "examples"),
    "gallery_dirs": "gallery",
    "filename_pattern": r"/plot_",  # only the plot_*.py scripts run when the docs build
    "download_all_examples": False,
    "abort_on_example_error": True,
    "remove_config_comments": True,
    # No sg_execution_times pages: they load jQuery, DataTables and Bootstrap from CDNs (the
    # site must read offline, tests/test_docs_site.py) and change at every build.
    "write_computation_times": False,
}

html_theme = "pydata_sphinx_theme"
html_title = f"ballscrew {__version__}"
html_theme_options = {
    "navigation_depth": 2,
    "show_toc_level": 2,
    "header_links_before_dropdown": 3,
}
os.environ.setdefault("MPLBACKEND", "Agg")  # the gallery's scripts draw off screen


def _draw_figures(app: object) -> None:
    """Draw docs/img/*.png (the README's and the pages' pictures) from this version."""
    subprocess.run([sys.executable, str(ROOT / "scripts" / "docs_figures.py")], check=True)


def _alias_signature(
    app: object, what: str, name: str, obj: object, options: object, sig: object, ret: object
) -> tuple[None, None] | None:
    """No signature for a type alias such as ``Block = tuple[...]`` (a module's data).

    numpydoc gives the alias the signature of ``tuple`` (it is callable), and Sphinx 9
    then fails on the data's empty signature list ("list assignment index out of range");
    answering first with a result Sphinx ignores leaves the alias without a signature.
    """
    if what == "data" and isinstance(obj, types.GenericAlias):
        return None, None
    return None


def setup(app: Any) -> dict[str, bool]:
    """Sphinx's hook: the pictures are drawn before the pages are read."""
    app.connect("builder-inited", _draw_figures)
    app.connect("autodoc-process-signature", _alias_signature, priority=100)
    return {"parallel_read_safe": True}
