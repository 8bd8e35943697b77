"""Run the code blocks of the Markdown docs and the README (Sybil), as a user would.

The root ``conftest.py`` hands Sybil the parsers below for ``README.md`` and
``docs/*.md``, so that ``pytest`` collects every code block as a test:

- a ``python`` block runs as it is, in the page's namespace (the blocks of a page run in
  order and share their names), with the working folder a temporary one;
- an ``output`` block is what the block before it prints: it is compared, line by line
  with trailing spaces ignored, with what that block printed (use it for deterministic
  outputs; a ``text`` block is shown and not checked);
- a ``sh`` block runs each of its commands in that temporary folder: ``ballscrew ...``
  through click's CliRunner in this process (it must exit with status 0), ``python ...``
  as a subprocess of this interpreter, and ``pip install .`` / ``pip install '.[X,Y]'``
  by checking that the extras it names are extras of pyproject.toml (the test
  environment has installed them). Any other command fails the block: mark such a block
  with ``% skip: next "why"`` in the Markdown;
- a block after a ``% write: NAME`` comment is a file the page names: it is written to
  NAME in the temporary folder (a case file, a measured CSV) before the commands that
  read it.

Skipping is Sybil's ``skip`` directive, visible in the Markdown (``% skip: next "why"``,
or ``<!-- skip: next "why" -->`` where ``%`` would show, as on GitHub's README). The
expensive blocks carry ``% skip: next if(not slow, reason="slow: why")``: ``slow`` is
false when pytest runs with ``-m "not slow"`` (``make test-fast``), true otherwise.
The folders ``examples/`` and ``src/`` of the repository are linked into the temporary
folder, so the commands naming ``examples/...`` or the bundled data find them.
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import tomllib
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

from sybil import Document, Example, Region, Sybil
from sybil.parsers.myst import CodeBlockParser, SkipParser

ROOT = Path(__file__).resolve().parents[1]
OUTPUT = "_docs_output"  # the namespace key of the last block's printed output
CWD = "_docs_cwd"

# ``% write: NAME`` (or ``<!-- write: NAME -->``) and the fenced block right after it.
WRITE = re.compile(
    r"^(?:%[ \t]*write:[ \t]*(?P<name>\S+)|<!--[ \t]*write:[ \t]*(?P<hname>\S+)[ \t]*-->)[ \t]*\n"
    r"(?P<fence>`{3,})[^\n]*\n(?P<body>.*?)^(?P=fence)[ \t]*$",
    re.MULTILINE | re.DOTALL,
)


def _extras() -> set[str]:
    project = tomllib.loads((ROOT / "pyproject.toml").read_text("utf-8"))["project"]
    return set(project["optional-dependencies"])


def _commands(source: str) -> list[list[str]]:
    """The commands of a shell block: continuation lines joined, comments dropped."""
    joined = re.sub(r"\\\n", " ", source)
    commands = []
    for line in joined.splitlines():
        argv = shlex.split(line, comments=True)
        if argv:
            commands.append(argv)
    return commands


def _run_ballscrew(argv: list[str]) -> str:
    """``ballscrew ARGV`` through the command's own entry point, in click's isolation."""
    from click.testing import CliRunner

    from ballscrew.cli import main

    with CliRunner().isolation() as (out, err, _):
        try:
            main(argv)
            status: object = 0
        except SystemExit as exc:
            status = exc.code or 0
        printed, told = out.getvalue().decode(), err.getvalue().decode()
    if status != 0:
        raise AssertionError(f"`ballscrew {shlex.join(argv)}` exited with {status}:\n{told}")
    return printed


def _check_pip(argv: list[str]) -> str:
    targets = [a for a in argv[2:] if not a.startswith("-")]
    if argv[:2] != ["pip", "install"] or not targets:
        raise AssertionError(f"not a `pip install` the docs test knows: {shlex.join(argv)}")
    for target in targets:
        match = re.fullmatch(r"\.(?:\[([\w,-]+)\])?", target)
        if match is None:
            raise AssertionError(f"`pip install {target}`: the docs install only this project")
        unknown = set(filter(None, (match.group(1) or "").split(","))) - _extras()
        if unknown:
            raise AssertionError(f"`pip install {target}`: no such extra {sorted(unknown)}")
    return ""


def _run_subprocess(program: list[str], argv: list[str]) -> str:
    done = subprocess.run([*program, *argv[1:]], capture_output=True, text=True, check=False)
    if done.returncode != 0:
        raise AssertionError(f"`{shlex.join(argv)}` exited with {done.returncode}:\n{done.stderr}")
    return done.stdout


def evaluate_shell(example: Example) -> None:
    """Run a ``sh`` block's commands (see the module's docstring)."""
    printed = []
    for argv in _commands(example.parsed):
        if argv[0] == "ballscrew" and ("--workers" in argv or "--scheduler" in argv):
            # A Dask cluster's worker processes start from a program of their own.
            printed.append(
                _run_subprocess([str(Path(sys.executable).with_name("ballscrew"))], argv)
            )
        elif argv[0] == "ballscrew":
            printed.append(_run_ballscrew(argv[1:]))
        elif argv[0] == "pip":
            printed.append(_check_pip(argv))
        elif argv[0] == "python":
            printed.append(_run_subprocess([sys.executable], argv))
        else:
            raise AssertionError(
                f"the docs test cannot run `{shlex.join(argv)}`; mark the block with "
                '`% skip: next "why"` if it is not to run'
            )
    example.namespace[OUTPUT] = "".join(printed)


def evaluate_python(example: Example) -> None:
    """Run a ``python`` block in the page's namespace, keeping what it prints."""
    buffer = io.StringIO()
    code = compile(example.parsed, example.path, "exec", dont_inherit=True)
    # The block's line numbers in a traceback are those of the Markdown file.
    code = code.replace(co_firstlineno=example.line + 1)
    with contextlib.redirect_stdout(buffer):
        exec(code, example.namespace)  # running the docs' code is the point
    example.namespace[OUTPUT] = buffer.getvalue()


def _lines(text: str) -> list[str]:
    return [line.rstrip() for line in text.rstrip().splitlines()]


def evaluate_output(example: Example) -> None:
    """Compare an ``output`` block with what the block before it printed."""
    printed = example.namespace.pop(OUTPUT, None)
    if printed is None:
        raise AssertionError("an output block with no block before it that printed")
    want, got = _lines(example.parsed), _lines(printed)
    if want != got:
        import difflib

        diff = "\n".join(difflib.unified_diff(want, got, "the docs show", "the code prints", n=1))
        raise AssertionError(f"the printed output differs from the docs:\n{diff}")


class WriteParser:
    """``% write: NAME`` then a fenced block: the block is a file written before the rest."""

    def __call__(self, document: Document) -> Iterable[Region]:
        for match in WRITE.finditer(document.text):
            name = match.group("name") or match.group("hname")
            yield Region(match.start(), match.end(), (name, match.group("body")), self.evaluate)

    @staticmethod
    def evaluate(example: Example) -> None:
        name, body = example.parsed
        Path(example.namespace[CWD], name).write_text(body, "utf-8")


def _setup(namespace: dict[str, Any]) -> None:
    import matplotlib

    matplotlib.use("Agg")
    folder = tempfile.mkdtemp(prefix="ballscrew-docs-")
    for name in ("examples", "src"):  # the commands name examples/ and the bundled data
        (Path(folder) / name).symlink_to(ROOT / name)
    namespace[CWD] = folder
    namespace["_docs_old_cwd"] = os.getcwd()
    namespace.setdefault("slow", True)
    os.chdir(folder)


def _teardown(namespace: dict[str, Any]) -> None:
    import matplotlib.pyplot as plt

    plt.close("all")
    os.chdir(namespace["_docs_old_cwd"])
    shutil.rmtree(namespace[CWD], ignore_errors=True)


def make_sybil(
    slow: Callable[[], bool] = lambda: True,
    patterns: Iterable[str] = ("README.md", "docs/*.md"),
    path: Path = ROOT,
) -> Sybil:
    """The Sybil that runs the docs' code blocks; while ``slow()`` is false, the blocks
    marked ``skip: next if(not slow, ...)`` are skipped."""

    def setup(namespace: dict[str, Any]) -> None:
        namespace["slow"] = slow()
        _setup(namespace)

    return Sybil(
        parsers=[
            WriteParser(),
            CodeBlockParser("python", evaluate_python),
            CodeBlockParser("sh", evaluate_shell),
            CodeBlockParser("output", evaluate_output),
            SkipParser(),
        ],
        patterns=list(patterns),
        excludes=["docs/_build/*"],
        setup=setup,
        teardown=_teardown,
        path=str(path),
    )
