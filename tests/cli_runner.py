"""Run the ``ballscrew`` command in-process for the tests."""

from __future__ import annotations

import pytest

from ballscrew.cli import main


def run(args: list[str], capsys: pytest.CaptureFixture[str]) -> tuple[int, str, str]:
    """Exit status, standard output and standard error of ``ballscrew ARGS``."""
    with pytest.raises(SystemExit) as info:
        main(args)
    out = capsys.readouterr()
    code = info.value.code
    return (code if isinstance(code, int) else 0), out.out, out.err
