"""A short, bounded run of the load test (benchmarks/load_web.py) against a real server."""

from __future__ import annotations

import importlib.util
import sys
from types import ModuleType

from shared import ROOT
from web_server import running_server


def _load_web() -> ModuleType:
    spec = importlib.util.spec_from_file_location("load_web", ROOT / "benchmarks" / "load_web.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules["load_web"] = module  # its dataclasses look their module up there
    spec.loader.exec_module(module)
    return module


def test_concurrent_clients_and_oversized_requests() -> None:
    load_web = _load_web()
    with running_server() as url:
        tally = load_web.run_load(url, clients=5, seconds=2.0)
        assert tally.errors == [] and tally.busy == 0
        # A request takes tens of milliseconds here: hundreds in 2 s; 20 leaves room
        # for a slow CI machine while still showing that every client was served.
        assert len(tally.latencies) >= 20
        refused = {what: (status, seconds) for what, status, seconds in load_web.refusals(url)}
    assert refused["1 MiB body with Content-Length"][0] == 413
    # Streamed without a length, the server answers once the limit is passed; the
    # client may still be sending and see the connection close (-1).
    assert refused["1 MiB body streamed in chunks"][0] in (413, -1)
    assert refused["a million speeds"][0] == 422
    # Refused before any work: milliseconds here (see the README); a second is far
    # above that and far below what a million points would take to compute.
    assert all(seconds < 1.0 for _, seconds in refused.values()), refused
