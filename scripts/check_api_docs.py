"""Check the built API reference: every public module has a page, each function and class an entry.

    .venv/bin/python scripts/check_api_docs.py docs/_build/html

Run by ``make docs`` after the build. A public module is one whose dotted name has no
part starting with an underscore; the functions and classes in its ``__all__`` must each
have an entry on its page (submodules have their own pages; constants, type aliases and
the click commands, which the command line's --help documents, are not checked). Exits
with status 1 and lists what is missing.
"""

from __future__ import annotations

import importlib
import inspect
import pkgutil
import sys
from pathlib import Path

import ballscrew


def public_modules() -> list[str]:
    """The dotted names of the package's public modules, the package first."""
    found = [
        m.name
        for m in pkgutil.walk_packages(ballscrew.__path__, "ballscrew.")
        if not any(part.startswith("_") for part in m.name.split(".")[1:])
    ]
    return ["ballscrew", *sorted(found)]


def missing_entries(html: Path) -> tuple[list[str], int]:
    """What the API reference under ``html`` lacks (pages, entries), and how many it checked."""
    missing, checked = [], 0
    for name in public_modules():
        page = html / "api" / f"{name}.html"
        if not page.is_file():
            missing.append(f"{name}: no page")
            continue
        text = page.read_text("utf-8")
        module = importlib.import_module(name)
        for member in getattr(module, "__all__", ()):
            obj = getattr(module, member)
            if not (inspect.isfunction(obj) or inspect.isclass(obj)):
                continue
            checked += 1
            if f'id="{name}.{member}"' not in text:
                missing.append(f"{name}.{member}: not on {page.name}")
    return missing, checked


def main() -> None:
    """Check the folder given on the command line (default docs/_build/html)."""
    html = Path(sys.argv[1] if len(sys.argv) > 1 else "docs/_build/html")
    missing, checked = missing_entries(html)
    for line in missing:
        print(f"API reference: {line}", file=sys.stderr)
    if missing or not checked:
        sys.exit(1)
    print(f"API reference: {len(public_modules())} module pages, {checked} functions and classes")


if __name__ == "__main__":
    main()
