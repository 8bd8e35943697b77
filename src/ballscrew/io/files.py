"""Atomic file output, safe against Ctrl-C and SIGTERM.

:func:`atomic_write` writes a file through a temporary file in the same
folder and an atomic rename, so a reader (or an interrupted run) sees either
the complete new file or the complete old one. Interrupting signals (SIGINT,
SIGTERM) that arrive while a file is being written are held back until the
file is complete, then delivered as usual: there is no moment at which a
temporary file exists that the unwinding code does not remove.

A process killed outright (SIGKILL, power loss) can still leave a temporary
file behind; :func:`sweep_temporaries` removes those of an earlier run before
a folder is written again.
"""

from __future__ import annotations

import contextlib
import os
import re
import secrets
import signal
import stat
import threading
from collections.abc import Callable, Iterator
from pathlib import Path
from types import FrameType
from typing import Any

__all__ = [
    "MAX_INPUT_BYTES",
    "OutputInUseError",
    "OutputSet",
    "atomic_folder",
    "atomic_write",
    "csv_rows",
    "deferred_signals",
    "exclusive_lock",
    "program_lines",
    "read_input_text",
    "swap_in",
    "sweep_stale_folders",
    "sweep_temporaries",
]

_HELD = (signal.SIGINT, signal.SIGTERM)
_TEMP_NAME = re.compile(r"^\..+\.[0-9a-f]{12}\.tmp$")


def _temporary(path: Path) -> Path:
    return path.parent / f".{path.name}.{secrets.token_hex(6)}.tmp"


_RECEIVED: list[int] = []


def record_signal(signum: int | None) -> None:
    """Record that SIGINT or SIGTERM arrived (``None`` forgets earlier ones).

    The command line's handlers call it before raising KeyboardInterrupt, so
    that a library which turns that exception into another one on its way up
    cannot make an interrupted run look like an internal error.
    """
    if signum is None:
        _RECEIVED.clear()
    else:
        _RECEIVED.append(signum)


def signal_received() -> bool:
    """Whether SIGINT or SIGTERM has arrived since the last ``record_signal(None)``."""
    return bool(_RECEIVED)


@contextlib.contextmanager
def deferred_signals() -> Iterator[None]:
    """Hold SIGINT and SIGTERM back for the duration of the block, then deliver them.

    Only the main thread can change signal handlers; elsewhere the block runs
    unprotected (Python runs signal handlers in the main thread only, so a
    worker thread is not interrupted by them anyway).
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    received: list[tuple[int, FrameType | None]] = []
    previous: dict[int, Any] = {}
    holding = [True]

    def hold(signum: int, frame: FrameType | None) -> None:
        if holding[0]:
            received.append((signum, frame))
        else:  # restored late: behave as the handler it replaced
            _deliver(previous.get(signum, signal.SIG_DFL), signum, frame)

    try:
        for sig in _HELD:
            previous[int(sig)] = signal.signal(sig, hold)
        yield
    finally:
        holding[0] = False
        for number, handler in previous.items():
            signal.signal(number, handler)
        if received:
            signum, frame = received[0]
            _deliver(previous[signum], signum, frame)


def _deliver(
    handler: Callable[[int, FrameType | None], Any] | int | None,
    signum: int,
    frame: FrameType | None,
) -> None:
    if callable(handler):
        handler(signum, frame)
    elif handler == signal.SIG_DFL:
        if signum == signal.SIGINT:
            raise KeyboardInterrupt
        os.kill(os.getpid(), signum)  # the default action, now that the handler is restored


def atomic_write(path: Path | str, data: bytes) -> None:
    """Write ``data`` where ``path`` points: a regular file atomically, anything else directly.

    - ``-`` is standard output.
    - A regular file (or a new name) is written through a temporary file in the same
      folder and an atomic rename, so a reader (or an interrupted run) sees either the
      complete new file or the complete old one. The file gets the permissions of any
      new file (the umask applies), not those of a private temporary file.
    - A symbolic link to a regular file keeps its link: the file it points to is
      replaced atomically.
    - A named pipe, a character device or a socket (or a link to one) is opened and
      written as it is: renaming a file over it would replace what the user pointed at.
    """
    if str(path) == "-":
        import sys

        sys.stdout.flush()
        sys.stdout.buffer.write(data)
        sys.stdout.buffer.flush()
        return
    path = Path(path)
    if not _is_regular_or_new(path):
        with open(path, "wb") as handle:  # a pipe, a device: written as it is
            handle.write(data)
        return
    if path.is_symlink():
        path = Path(os.path.realpath(path))  # the link stays; its target is replaced
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = _temporary(path)
    with deferred_signals():
        try:
            with open(tmp, "xb") as handle:
                handle.write(data)
                handle.flush()
                os.fsync(handle.fileno())
            os.replace(tmp, path)
        except BaseException:
            tmp.unlink(missing_ok=True)
            raise


def _is_regular_or_new(path: Path) -> bool:
    """Whether ``path`` (followed through links) is a regular file or does not exist yet."""
    try:
        mode = os.stat(path).st_mode
    except (FileNotFoundError, NotADirectoryError):
        return True  # a new file (or a dangling link: its target is created); mkdir says why not
    return stat.S_ISREG(mode)


def sweep_temporaries(folder: Path) -> int:
    """Remove temporary files that :func:`atomic_write` left in ``folder`` when killed.

    Returns how many were removed. Only names of the form
    ``.<name>.<12 hex digits>.tmp`` are touched.
    """
    removed = 0
    if not Path(folder).is_dir():
        return 0
    for entry in Path(folder).iterdir():
        if entry.is_file() and _TEMP_NAME.match(entry.name):
            entry.unlink(missing_ok=True)
            removed += 1
    return removed


@contextlib.contextmanager
def atomic_folder(folder: Path) -> Iterator[Path]:
    """A report folder written whole: files go to a sibling, swapped in when all are written.

    Yields the temporary folder (``.<name>.<pid>-<hex>.new`` beside ``folder``). When
    the block ends normally, ``folder`` (if any) is moved aside and the new one
    renamed into its place, under :func:`deferred_signals`, so the folder is
    always either the earlier run's, whole, or this run's, whole: never a mix.
    When the block raises (Ctrl-C included) the temporary folder is removed and
    ``folder`` is left as it was. A run killed outright leaves its temporary folder
    behind: the next run into the same folder removes it (:func:`sweep_stale_folders`).
    A symbolic link to a folder is followed: the folder it points to is replaced, and the
    link stays (renaming over it would hide the link and leave the folder as it was).
    """
    folder = Path(folder)
    if folder.is_symlink():
        folder = Path(os.path.realpath(folder))
    folder.parent.mkdir(parents=True, exist_ok=True)
    sweep_stale_folders(folder)
    tmp = folder.parent / f".{folder.name}.{os.getpid()}-{secrets.token_hex(6)}.new"
    tmp.mkdir()
    try:
        yield tmp
        old = folder.parent / f".{folder.name}.{os.getpid()}-{secrets.token_hex(6)}.old"
        if swap_in(tmp, folder, aside=old):
            _remove_tree(old)
    except BaseException:
        _remove_tree(tmp)
        raise


_FOLDER_TEMP = re.compile(r"^\.(?P<name>.+)\.(?:(?P<pid>\d+)-)?[0-9a-f]{12}\.(?:new|old)$")


def sweep_stale_folders(folder: Path) -> int:
    """Remove the temporary siblings of ``folder`` that killed runs of :func:`atomic_folder` left.

    A sibling ``.<name>.<pid>-<hex>.new`` (or ``.old``) is removed when its process no
    longer runs, so a run in progress keeps its own; one without a process id (written
    by a release before 0.3.0) is removed too. Returns how many were removed.
    """
    folder = Path(folder)
    if not folder.parent.is_dir():
        return 0
    removed = 0
    for entry in folder.parent.iterdir():
        match = _FOLDER_TEMP.match(entry.name)
        if not match or match["name"] != folder.name or not entry.is_dir():
            continue
        if match["pid"] is not None and _alive(int(match["pid"])):
            continue
        _remove_tree(entry)
        removed += 1
    return removed


def _alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # another user's process: running
        return True
    return True


def swap_in(new: Path, target: Path, *, aside: Path) -> bool:
    """Rename ``new`` to ``target``, moving an existing ``target`` to ``aside`` first.

    Both renames happen under :func:`deferred_signals`, so an interrupt leaves
    ``target`` whole: the earlier one or the new one. Returns whether an earlier
    ``target`` was moved aside (the caller removes ``aside`` then).
    """
    with deferred_signals():
        moved = target.exists()
        if moved:
            target.rename(aside)
        new.rename(target)
    return moved


def _remove_tree(path: Path) -> None:
    import shutil

    shutil.rmtree(path, ignore_errors=True)


class OutputInUseError(OSError):
    """Another run holds the lock of an output (its message says which process)."""


@contextlib.contextmanager
def exclusive_lock(path: Path) -> Iterator[None]:
    """Hold an exclusive lock on ``path`` (a lock file, created) while the block runs.

    The operating system releases the lock when the process ends, however it
    ends, so a killed run never leaves a stale lock. The file names the holder
    (process id and start time) for the message another run gets, and is
    removed when the block ends. Raises :class:`OutputInUseError` at once when
    another process holds it.
    """
    import fcntl
    import time

    path = Path(path)
    while True:
        fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            holder = os.pread(fd, 200, 0).decode("utf-8", "replace").strip()
            os.close(fd)
            raise OutputInUseError(holder or "another process") from None
        # The previous holder removes the file when done: lock the file that is there now.
        with contextlib.suppress(OSError):
            if os.stat(path).st_ino == os.fstat(fd).st_ino:
                break
        os.close(fd)
    os.ftruncate(fd, 0)
    os.write(fd, f"process {os.getpid()}, since {time.strftime('%H:%M:%S')}".encode())
    try:
        yield
    finally:
        with contextlib.suppress(OSError):
            os.unlink(path)
        os.close(fd)


MAX_INPUT_BYTES = 50 * 1024 * 1024
"""The largest input file read [bytes]: 50 MiB, far above any case, sweep, profile or
measured curve (a 1e6-row trajectory CSV is about 40 MB), and below what would hold a
run for minutes before it is refused."""


def read_input_text(field: str, path: str | Path) -> str:
    """The text of an input file; a :class:`~ballscrew.errors.BallScrewInputError` names ``field``.

    Only a regular file (or a link to one) is read: a named pipe could wait for a writer
    forever and a device such as ``/dev/zero`` never ends, so both are refused by name,
    as are a folder, a file larger than :data:`MAX_INPUT_BYTES` and text that is not
    UTF-8.
    """
    from ..errors import BallScrewInputError

    file = Path(path)
    try:
        info = os.stat(file)
    except OSError as exc:
        raise BallScrewInputError(field, str(file), f"a readable file ({exc.strerror})") from None
    if not stat.S_ISREG(info.st_mode):
        kind = "a folder" if stat.S_ISDIR(info.st_mode) else "a pipe or a device"
        raise BallScrewInputError(field, str(file), f"a regular file (this is {kind})")
    if info.st_size > MAX_INPUT_BYTES:
        raise BallScrewInputError(
            field, str(file), f"a file of at most {MAX_INPUT_BYTES // 2**20} MiB "
            f"(this one has {info.st_size / 2**20:.0f} MiB)"
        )  # fmt: skip
    try:
        with open(file, "rb") as handle:
            data = handle.read(MAX_INPUT_BYTES + 1)
    except OSError as exc:
        raise BallScrewInputError(field, str(file), f"a readable file ({exc.strerror})") from None
    if len(data) > MAX_INPUT_BYTES:  # grew while being read
        raise BallScrewInputError(field, str(file), f"a file of at most {MAX_INPUT_BYTES} bytes")
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        raise BallScrewInputError(field, str(file), "a UTF-8 text file") from None


def csv_rows(text: str, source: str, delimiter: str | None = None) -> tuple[list[list[str]], str]:
    r"""The rows of CSV ``text`` (a leading byte-order mark dropped) and their separator.

    ``delimiter`` None: the first non-blank line's, a semicolon or a tab (spreadsheets in
    decimal-comma locales) else a comma. What the CSV module cannot read (a cell past its
    field limit of 131 072 characters, a stray quote in strict files) is an input error
    naming ``source`` and the line, not an internal error.

    >>> csv_rows("a [s];b [m]\n1;2\n", "trace.csv")
    ([['a [s]', 'b [m]'], ['1', '2']], ';')
    """
    import csv
    import io

    from ..errors import BallScrewInputError

    text = text.lstrip("\ufeff")
    if delimiter is None:
        first = next((line for line in text.splitlines() if line.strip()), "")
        delimiter = ";" if ";" in first else ("\t" if "\t" in first else ",")
    reader = csv.reader(io.StringIO(text), delimiter=delimiter)
    try:
        return list(reader), delimiter
    except csv.Error as exc:
        raise BallScrewInputError(
            f"{source}: line {reader.line_num}", f"({exc})",
            f"cells of at most {csv.field_size_limit()} characters, in a CSV file",
        ) from None  # fmt: skip


class OutputSet:
    """A run's outputs (files and report folders) put in place together, or not at all.

    Used as a context manager: each output added is staged at once (a file's bytes in a
    temporary file beside it, a folder built in a temporary sibling); when the block ends
    normally, all are renamed into place one after the other under
    :func:`deferred_signals` (Ctrl-C and SIGTERM wait), and when it raises, every staged
    output is removed. So a run stopped while it computes or stages leaves every earlier
    output as it was, never a new CSV beside an old report. Standard output (``-``) and
    what is not a regular file (a pipe, a device) are written when the set is put in
    place, as they are. Links are followed as :func:`atomic_write` and
    :func:`atomic_folder` follow them.

    >>> import tempfile
    >>> where = Path(tempfile.mkdtemp())
    >>> with OutputSet() as out:
    ...     out.file(where / "a.csv", b"x")
    ...     out.folder(where / "rep", lambda f: (f / "r.md").write_text("r"))
    >>> sorted(p.name for p in where.iterdir())
    ['a.csv', 'rep']
    """

    def __init__(self) -> None:
        self._staged: list[tuple[Path, Path]] = []  # temporary file -> its place
        self._built: list[tuple[Path, Path]] = []  # temporary folder -> its place
        self._direct: list[tuple[Path | str, bytes]] = []

    def __enter__(self) -> OutputSet:
        return self

    def __exit__(self, kind: object, error: object, trace: object) -> None:
        if kind is None:
            self._put()
        else:
            self._discard()

    def file(self, path: Path | str, data: bytes) -> None:
        """Stage a file (``-``: standard output) with its bytes."""
        if str(path) == "-" or not _is_regular_or_new(Path(path)):
            self._direct.append((path, data))
            return
        place = Path(os.path.realpath(path)) if Path(path).is_symlink() else Path(path)
        place.parent.mkdir(parents=True, exist_ok=True)
        tmp = _temporary(place)
        with open(tmp, "xb") as handle:
            self._staged.append((tmp, place))
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())

    def folder(self, path: Path | str, write: Callable[[Path], object]) -> None:
        """Stage a report folder that ``write(folder)`` fills."""
        folder = Path(path)
        place = Path(os.path.realpath(folder)) if folder.is_symlink() else folder
        place.parent.mkdir(parents=True, exist_ok=True)
        sweep_stale_folders(place)
        tmp = place.parent / f".{place.name}.{os.getpid()}-{secrets.token_hex(6)}.new"
        tmp.mkdir()
        self._built.append((tmp, place))
        write(tmp)

    def _discard(self) -> None:
        for tmp, _ in self._staged:
            tmp.unlink(missing_ok=True)
        for tmp, _ in self._built:
            _remove_tree(tmp)

    def _put(self) -> None:
        aside: list[Path] = []
        with deferred_signals():
            for tmp, place in self._staged:
                os.replace(tmp, place)
            for tmp, place in self._built:
                old = place.parent / f".{place.name}.{os.getpid()}-{secrets.token_hex(6)}.old"
                if place.exists():
                    place.rename(old)
                    aside.append(old)
                tmp.rename(place)
        for old in aside:
            _remove_tree(old)
        for path, data in self._direct:
            atomic_write(path, data)


def program_lines(text: str) -> list[str]:
    r"""A text's lines as a program's line numbers count them: at CR LF, LF or CR only.

    Python's ``splitlines`` also breaks at a form feed, a vertical tab and the Unicode line
    separators, which a G-code control reads as characters of a line: a form feed that a
    post writes as a page break would shift every line number after it.

    >>> program_lines("G1 X1\r\n\fG1 X2\nG1 X3")
    ['G1 X1', '\x0cG1 X2', 'G1 X3']
    """
    if not text:
        return []
    return re.split(r"\r\n|\r|\n", text.removesuffix("\n").removesuffix("\r"))
