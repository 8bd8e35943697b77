"""Mutation testing as scripts/mutate.py does it, in one pytest session with a fork per mutant.

    .venv/bin/python scripts/mutate_forked.py src/ballscrew/program/sinumerik.py \
        --tests tests/program/test_sinumerik.py src/ballscrew/program/sinumerik.py

The same mutants (:func:`mutate.mutants`, :func:`mutate.mutated`) and the same verdict: a
mutant is killed when the tests, run in order and stopped at the first failure (``-x``), fail
(or hang past ``--timeout``, or grow past ``--memory``). The tests are collected once; each
mutant runs in a forked child that executes the mutated source into the module, rebinds the
names other modules (and the module's doctests) took from it, and runs the collected tests.
What the children share is the libraries imported and, with ``--warm FILE``, what running
FILE in the parent filled in (the lazy imports and the data caches of the other modules), so
that a mutant costs its tests' own time only. The module file on disk is never changed.

Each mutant's verdict is printed as it comes, a killed one with the first test that failed.
Not part of the CI run.
"""

from __future__ import annotations

import argparse
import os
import resource
import signal
import sys
import time
import types
import warnings
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from mutate import mutants, mutated

_SKIP = (int, bool, str, bytes, type(None))
"""Values never rebound in other modules: interned, so identity says nothing."""


class _ForkPlugin:
    def __init__(self, args: argparse.Namespace, name: str, path: str) -> None:
        self.args, self.name, self.path = args, name, path
        self.lines = {int(x) for x in args.lines.split(",") if x.strip()}
        self.child = 0

    def _child(self, session: pytest.Session, source: str | None) -> None:
        limit = int(self.args.memory * 2**30)
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
        if not self.args.debug:
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, 1)
            os.dup2(devnull, 2)
        mod = sys.modules[self.name]
        if source is not None:
            old = dict(mod.__dict__)
            exec(compile(source, self.path, "exec"), mod.__dict__)
            swap = {id(v): mod.__dict__.get(k) for k, v in old.items()
                    if not k.startswith("__") and mod.__dict__.get(k) is not v
                    and not isinstance(v, _SKIP)}  # fmt: skip
            for other in list(sys.modules.values()):
                if other is mod or not isinstance(other, types.ModuleType):
                    continue
                names = getattr(other, "__dict__", None) or {}
                for k, v in list(names.items()):
                    if id(v) in swap and not isinstance(v, _SKIP):
                        names[k] = swap[id(v)]
        items = session.items
        for item in items:
            test = getattr(item, "dtest", None)
            if test is not None and test.globs.get("__name__") == self.name:
                test.globs.update(mod.__dict__)
        for i, item in enumerate(items):
            after = items[i + 1] if i + 1 < len(items) else None
            item.config.hook.pytest_runtest_protocol(item=item, nextitem=after)
            if session.testsfailed:
                Path(f"{self.args.report}.{os.getppid()}").write_text(item.nodeid, "utf-8")
                os._exit(1)
        os._exit(0)

    def _passes(self, session: pytest.Session, source: str | None) -> bool:
        pid = os.fork()
        if pid == 0:
            signal.signal(signal.SIGTERM, signal.SIG_DFL)
            try:
                self._child(session, source)
            finally:
                os._exit(3)
        self.child = pid
        start = time.monotonic()
        while True:
            done, status = os.waitpid(pid, os.WNOHANG)
            if done:
                self.child = 0
                return os.waitstatus_to_exitcode(status) == 0
            if time.monotonic() - start > self.args.timeout:
                os.kill(pid, signal.SIGKILL)
                os.waitpid(pid, 0)
                self.child = 0
                return False
            time.sleep(0.02)

    def pytest_runtest_logreport(self, report: pytest.TestReport) -> None:
        if report.failed and self.args.debug:
            print(report.nodeid, report.longreprtext[-3000:], file=sys.__stderr__, flush=True)

    @pytest.hookimpl(tryfirst=True)
    def pytest_runtestloop(self, session: pytest.Session) -> bool:
        out = sys.__stdout__
        original = Path(self.path).read_text("utf-8")
        todo = mutants(original)
        if self.lines:
            todo = [m for m in todo if m.line in self.lines]
        if self.args.warm:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                exec(Path(self.args.warm).read_text("utf-8"), {"__name__": "warm"})
        if not self._passes(session, None):
            print("the tests fail on the unmutated module", file=out, flush=True)
            session.testsfailed = 1
            return True
        survivors = []
        start = time.monotonic()
        report = Path(f"{self.args.report}.{os.getpid()}")
        signal.signal(signal.SIGTERM, signal.default_int_handler)
        try:
            for m in todo:
                report.unlink(missing_ok=True)
                where = f"line {m.line}, column {m.column}: {m.text}"
                if self._passes(session, mutated(original, m.index)):
                    survivors.append(m)
                    print(f"  survived: {where}", file=out, flush=True)
                else:
                    by = report.read_text("utf-8") if report.exists() else "a timeout or crash"
                    print(f"  killed: {where} by {by}", file=out, flush=True)
        finally:
            if self.child:
                os.kill(self.child, signal.SIGKILL)
                os.waitpid(self.child, 0)
            report.unlink(missing_ok=True)
        print(
            f"{self.path}: {len(todo)} mutants, {len(todo) - len(survivors)} killed, "
            f"{len(survivors)} survived ({time.monotonic() - start:.0f} s)",
            file=out,
        )
        for m in survivors:
            print(f"  survived: line {m.line}, column {m.column}: {m.text}", file=out)
        return True


def main() -> None:
    """Run the mutants of one module and report the survivors."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("file", type=Path, help="the module, under src/")
    parser.add_argument("--tests", nargs="+", required=True, help="pytest targets")
    parser.add_argument("--lines", default="", help="only the mutants on these lines")
    parser.add_argument("--timeout", type=float, default=300.0, help="seconds per mutant")
    parser.add_argument("--memory", type=float, default=4.0, help="GiB per mutant")
    parser.add_argument("--warm", default="", help="a Python file run once in the parent")
    parser.add_argument("--report", default="/tmp/mutate-forked", help="the killer's file")
    parser.add_argument("--debug", action="store_true", help="show the children's output")
    args = parser.parse_args()
    path = args.file.resolve()
    name = ".".join(path.relative_to(Path("src").resolve()).with_suffix("").parts)
    plugin = _ForkPlugin(args, name, str(path))
    sys.exit(pytest.main(["-q", "-p", "no:cacheprovider", *args.tests], plugins=[plugin]))


if __name__ == "__main__":
    main()
