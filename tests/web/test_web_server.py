"""The served calculator keeps answering with idle and slow connections open (issue 28).

Before, uvicorn capped connections at 64: 63 idle ones turned every other request into
a plain-text 503 for as long as they stayed open, and a connection that never sent a
whole request head was never closed.
"""

from __future__ import annotations

import socket
import time
import urllib.request

import pytest

from ballscrew.web import server
from web_server import running_server


def _connect(url: str) -> socket.socket:
    host, port = url.removeprefix("http://").split(":")
    return socket.create_connection((host, int(port)), timeout=5)


@pytest.mark.slow
def test_the_page_answers_with_150_idle_connections_open() -> None:
    with running_server() as url:
        idle = [_connect(url) for _ in range(150)]
        try:
            start = time.perf_counter()
            with urllib.request.urlopen(url + "/", timeout=10) as page:
                assert page.status == 200
            assert time.perf_counter() - start < 2.0
        finally:
            for s in idle:
                s.close()


def test_a_connection_too_slow_with_its_head_is_closed(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(server, "HEAD_SECONDS", 0.5)
    with running_server() as url:
        slow = _connect(url)
        slow.sendall(b"GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n")  # the head never ends
        start = time.perf_counter()
        slow.settimeout(5.0)
        assert slow.recv(1024) == b""  # closed by the server
        assert time.perf_counter() - start < 3.0
        slow.close()
        # A whole request on a fresh connection is answered as ever.
        with urllib.request.urlopen(url + "/", timeout=10) as page:
            assert page.status == 200
