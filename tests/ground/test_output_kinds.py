"""Outputs go where the user points (issue 35): a pipe, a device or a link is not replaced.

Each kind of output path is written once through ``atomic_write``, then its kind is
checked: a named pipe stays a pipe (and its reader gets the bytes), a character
device stays a device, a link stays a link whose target holds the new bytes, ``-`` is
standard output. Killed runs' temporary report folders are removed by the next run into
the same folder, but never a folder of a run still going.
"""

from __future__ import annotations

import os
import stat
import subprocess
import sys
import threading
from pathlib import Path

import pytest

from ballscrew.io.files import atomic_folder, atomic_write, sweep_stale_folders


def test_a_named_pipe_is_written_as_a_pipe(tmp_path: Path) -> None:
    fifo = tmp_path / "out.json"
    os.mkfifo(fifo)
    got: list[bytes] = []
    reader = threading.Thread(target=lambda: got.append(fifo.read_bytes()))
    reader.start()
    atomic_write(fifo, b"through the pipe")
    reader.join(timeout=10)
    assert got == [b"through the pipe"]
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)


@pytest.mark.parametrize("linked", [False, True])
def test_a_character_device_stays_a_device(tmp_path: Path, linked: bool) -> None:
    target = Path(os.devnull)
    path = tmp_path / "null" if linked else target
    if linked:
        path.symlink_to(target)
    atomic_write(path, b"discarded")
    assert stat.S_ISCHR(os.stat(target).st_mode)
    assert not linked or path.is_symlink()
    assert sorted(p.name for p in tmp_path.iterdir()) == (["null"] if linked else [])


def test_a_link_to_a_file_keeps_its_link_and_replaces_the_target(tmp_path: Path) -> None:
    real = tmp_path / "data" / "result.csv"
    real.parent.mkdir()
    real.write_bytes(b"old")
    link = tmp_path / "result.csv"
    link.symlink_to(real)
    atomic_write(link, b"new")
    assert link.is_symlink() and os.readlink(link) == str(real)
    assert real.read_bytes() == b"new"
    assert sorted(p.name for p in real.parent.iterdir()) == ["result.csv"]  # no temporary


def test_a_dash_is_standard_output() -> None:
    code = "from ballscrew.io.files import atomic_write; atomic_write('-', b'to stdout')"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, check=True)
    assert out.stdout == b"to stdout"


def test_a_killed_runs_folder_is_removed_and_a_live_runs_kept(tmp_path: Path) -> None:
    # A process that has ended: its id is free (reused ids are improbable within the test).
    ended = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                           capture_output=True, text=True, check=True)  # fmt: skip
    dead = tmp_path / f".report.{int(ended.stdout)}-0123456789ab.new"
    old_style = tmp_path / ".report.0123456789ab.old"  # a release before 0.3.0
    live = tmp_path / f".report.{os.getppid()}-0123456789ab.new"  # the parent runs
    other = tmp_path / f".other.{int(ended.stdout)}-0123456789ab.new"  # another folder's
    for d in (dead, old_style, live, other):
        d.mkdir()
    assert sweep_stale_folders(tmp_path / "report") == 2
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([live.name, other.name])
    with atomic_folder(tmp_path / "report") as tmp:
        (tmp / "a.txt").write_text("a")
    assert (tmp_path / "report" / "a.txt").read_text() == "a"


def test_an_input_that_is_no_regular_file_is_refused_by_name(tmp_path: Path) -> None:
    from ballscrew.errors import BallScrewInputError
    from ballscrew.io.files import read_input_text

    fifo = tmp_path / "case.toml"
    os.mkfifo(fifo)  # 0.2.0 waited for a writer forever
    for path, why in [(fifo, "pipe or a device"), (Path("/dev/zero"), "pipe or a device"),
                      (tmp_path, "folder"), (tmp_path / "none.toml", "No such file")]:  # fmt: skip
        with pytest.raises(BallScrewInputError, match="--case") as err:
            read_input_text("--case", path)
        assert why in str(err.value)
    text = tmp_path / "ok.toml"
    text.write_bytes("title = 'Fräse'\n".encode())
    assert read_input_text("--case", text) == "title = 'Fräse'\n"
    text.write_bytes(b"\xff\xfe")
    with pytest.raises(BallScrewInputError, match="UTF-8"):
        read_input_text("--case", text)
