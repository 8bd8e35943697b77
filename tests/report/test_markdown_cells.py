"""A report's Markdown table keeps its columns whatever its cells say."""

from __future__ import annotations

from ballscrew.report.document import Block, markdown


def test_a_bar_in_a_cell_is_escaped_not_a_new_column() -> None:
    # check's lift-off row cites '|F| = 2^1.5 F_pr': unescaped, its row had two columns more
    # than its header and the table broke in every Markdown viewer (a newcomer's trial).
    text = markdown([Block("table", (["criterion", "source"], [["lift-off", "|F| = 2^1.5 F_pr"]]))])
    header, _, row = text.strip().splitlines()
    unescaped = row.replace("\\|", "")
    assert unescaped.count("|") == header.count("|") == 3
    assert "\\|F\\|" in row
