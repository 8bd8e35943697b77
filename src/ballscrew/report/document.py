"""A tiny document model (headings, paragraphs, lists, tables, figures) as Markdown and HTML.

The reports of ``ballscrew study`` and ``ballscrew energy`` are lists of
:class:`Block`; :func:`markdown` and :func:`html_page` render them (the HTML
page self-contained, figures embedded as PNG).
"""

from __future__ import annotations

import base64
import html
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..io.files import atomic_write

__all__ = ["Block", "html_page", "markdown", "write_data", "write_pages"]


@dataclass(frozen=True)
class Block:
    """One block: a kind (h1, h2, p, ul, table or img) and its content."""

    kind: str  # "h1", "h2", "p", "ul", "table", "img"
    content: Any


def _cell(value: object) -> str:
    """A Markdown table cell: a '|' in it (the lift-off row's |F|) escaped, not a new column."""
    return str(value).replace("|", "\\|")


def markdown(blocks: list[Block]) -> str:
    """The blocks as Markdown (figures linked as figures/KEY.png, .svg and data/KEY.csv)."""
    out: list[str] = []
    for b in blocks:
        if b.kind == "h1":
            out.append(f"# {b.content}\n")
        elif b.kind == "h2":
            out.append(f"## {b.content}\n")
        elif b.kind == "p":
            out.append(f"{b.content}\n")
        elif b.kind == "ul":
            out.append("\n".join(f"- {item}" for item in b.content) + "\n")
        elif b.kind == "table":
            header, rows = b.content
            out.append("| " + " | ".join(_cell(h) for h in header) + " |")
            out.append("|" + "---|" * len(header))
            out.extend("| " + " | ".join(_cell(c) for c in row) + " |" for row in rows)
            out.append("")
        elif b.kind == "img":
            key, caption = b.content
            out.append(
                f"![{caption}](figures/{key}.png)\n\n*{caption}* "
                f"([SVG](figures/{key}.svg), [data](data/{key}.csv))\n"
            )
    return "\n".join(out)


def html_page(blocks: list[Block], title: str, images: dict[str, bytes]) -> str:
    """The blocks as one self-contained HTML page; ``images`` maps figure keys to PNG bytes."""
    parts = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        f"<title>{html.escape(title)}</title>",
        "<style>body{font-family:sans-serif;max-width:60em;margin:2em auto;line-height:1.45}"
        "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #bbb;"
        "padding:.25em .6em;text-align:left}img{max-width:100%}figcaption{font-style:italic}"
        "</style></head><body>",
    ]
    for b in blocks:
        if b.kind in ("h1", "h2"):
            parts.append(f"<{b.kind}>{html.escape(b.content)}</{b.kind}>")
        elif b.kind == "p":
            parts.append(f"<p>{html.escape(b.content)}</p>")
        elif b.kind == "ul":
            parts.append(
                "<ul>" + "".join(f"<li>{html.escape(i)}</li>" for i in b.content) + "</ul>"
            )
        elif b.kind == "table":
            header, rows = b.content
            parts.append(
                "<table><tr>" + "".join(f"<th>{html.escape(h)}</th>" for h in header) + "</tr>"
            )
            for row in rows:
                parts.append(
                    "<tr>" + "".join(f"<td>{html.escape(str(c))}</td>" for c in row) + "</tr>"
                )
            parts.append("</table>")
        elif b.kind == "img":
            key, caption = b.content
            data = base64.b64encode(images[key]).decode("ascii")
            parts.append(
                f'<figure><img alt="{html.escape(caption)}" '
                f'src="data:image/png;base64,{data}">'
                f"<figcaption>{html.escape(caption)}</figcaption></figure>"
            )
    parts.append("</body></html>\n")
    return "\n".join(parts)


def write_pages(
    folder: Path, blocks: list[Block], title: str, images: dict[str, bytes]
) -> list[Path]:
    """``report.md`` and the self-contained ``report.html`` of ``blocks`` in ``folder``."""
    written = []
    for name, text in (("report.md", markdown(blocks)),
                       ("report.html", html_page(blocks, title, images))):  # fmt: skip
        atomic_write(folder / name, text.encode("utf-8"))
        written.append(folder / name)
    return written


def write_data(folder: Path, tables: Iterable[tuple[str, bytes]]) -> list[Path]:
    """Each (name, CSV bytes) as ``data/NAME.csv`` in ``folder``."""
    written = []
    for key, content in tables:
        path = folder / "data" / f"{key}.csv"
        atomic_write(path, content)
        written.append(path)
    return written
