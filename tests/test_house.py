"""The house's size rules (issue 49, "long bodies").

- At most :data:`MAX_LONG_FUNCTIONS` functions in ``src/`` have :data:`LONG_BODY` or
  more code lines, and each of them has a docstring. Code lines are the body's
  lines that are neither blank nor a comment, the docstring left out.
- A module over :data:`LONG_MODULE` lines says why at its top: the word "long"
  in its docstring's summary line or the paragraph after it.

The two functions left over the line are the helix's compiled loop (one numba kernel,
whose body is the loop over points) and the thermal steady state's solver; each has its
docstring.
"""

from __future__ import annotations

import ast
import re
import textwrap
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src"
LONG_BODY = 80
MAX_LONG_FUNCTIONS = 2
LONG_MODULE = 800


def code_lines(lines: list[str], node: ast.FunctionDef | ast.AsyncFunctionDef) -> int:
    """The function's body lines that are neither blank nor a comment, its docstring out."""
    body = node.body
    if ast.get_docstring(node, clean=False) is not None:
        body = body[1:]
    if not body:
        return 0
    span = lines[body[0].lineno - 1 : node.end_lineno]
    return sum(1 for line in span if line.strip() and not line.strip().startswith("#"))


def long_functions(root: Path) -> dict[str, tuple[int, bool]]:
    """``path:name`` of every function of :data:`LONG_BODY`+ code lines: (lines, documented)."""
    found = {}
    for path in sorted(root.rglob("*.py")):
        text = path.read_text(encoding="utf-8")
        lines = text.splitlines()
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
                n = code_lines(lines, node)
                if n >= LONG_BODY:
                    key = f"{path.relative_to(root).as_posix()}:{node.name}"
                    found[key] = (n, ast.get_docstring(node) is not None)
    return found


def unexplained_modules(root: Path) -> list[str]:
    """Modules over :data:`LONG_MODULE` lines whose docstring's top does not say "long"."""
    bad = []
    for path in sorted(root.rglob("*.py")):
        text = path.read_text(encoding="utf-8")
        if len(text.splitlines()) <= LONG_MODULE:
            continue
        doc = ast.get_docstring(ast.parse(text)) or ""
        top = "\n\n".join(doc.split("\n\n")[:2])  # the summary line and the paragraph after
        if not re.search(r"\blong\b", top, re.IGNORECASE):
            bad.append(path.relative_to(root).as_posix())
    return bad


def test_code_lines_leave_out_blanks_comments_and_the_docstring() -> None:
    # Counted by hand: 3 statements, 1 comment line, 2 blank lines, a 3-line docstring,
    # a 1-line string that is not the first statement (counted, it is code).
    source = textwrap.dedent(
        '''
        def f(x):
            """Doc.

            More doc.
            """
            y = x + 1

            # a comment
            z = y * 2

            "not a docstring"
            return z
        '''
    )
    node = ast.parse(source).body[0]
    assert isinstance(node, ast.FunctionDef)
    assert code_lines(source.splitlines(), node) == 4


def test_long_functions_are_found_and_counted(tmp_path: Path) -> None:
    # One function of exactly LONG_BODY code lines (found) and one of one fewer (not),
    # each with blank and comment lines between that must not count.
    body = "\n".join(f"    a{i} = {i}\n\n    # note {i}" for i in range(LONG_BODY - 1))
    text = f'def just(x):\n    """Doc."""\n{body}\n    return x\n\n\ndef short(x):\n{body}\n'
    (tmp_path / "m.py").write_text(text, encoding="utf-8")
    assert long_functions(tmp_path) == {"m.py:just": (LONG_BODY, True)}


def test_at_most_two_long_functions_each_documented() -> None:
    found = long_functions(SRC)
    assert len(found) <= MAX_LONG_FUNCTIONS, found
    assert all(doc for _, doc in found.values()), found


def test_every_long_module_says_why() -> None:
    assert unexplained_modules(SRC) == []
