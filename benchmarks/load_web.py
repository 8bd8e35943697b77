"""Load test of the web calculator's API on this machine's loopback interface.

Run with ``.venv/bin/python benchmarks/load_web.py`` (defaults: 20 clients for
30 s). It starts ``ballscrew serve`` on a free loopback port in a
subprocess (or uses ``--url``, which must be a loopback address), then:

1. each client, on its own kept-alive connection, posts the same request to
   ``POST /api/torque`` (the README's reference double nut, complete model,
   50 speeds) one after another until the time is up; it prints the
   requests, errors, throughput and the median, 95th-percentile and largest
   latency;
2. an oversized body (1 MiB, 16 times the limit) declared by its
   ``Content-Length``, the same body streamed in chunks with no length, and
   a grid of a million speeds: the time until each is refused, and its status.

Bounded in count and time: at most 100 clients, 120 s and 100,000 requests
per client; every connection goes to the loopback interface only.
"""

from __future__ import annotations

import argparse
import http.client
import ipaddress
import json
import socket
import statistics
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from dataclasses import dataclass, field
from urllib.parse import urlsplit

REQUEST = {
    "screw": {"designation": "40x10 double 2.5x2 6.35", "preload": "2 kN"},
    "lubricant": {"name": "PAO ISO VG 68"},
    "model": "complete",
    "speed": "10..3000:50 rpm",
    "temperature": "40 degC",
    "axial_load": "1 kN",
}
MAX_CLIENTS = 100
MAX_SECONDS = 120.0
MAX_REQUESTS_PER_CLIENT = 100_000


@dataclass
class Tally:
    """What the clients saw."""

    latencies: list[float] = field(default_factory=list)
    errors: list[str] = field(default_factory=list)
    busy: int = 0  # 503 answers: the server refused for load, not for an error
    lock: threading.Lock = field(default_factory=threading.Lock)


def _loopback(url: str) -> tuple[str, int]:
    parts = urlsplit(url)
    host = parts.hostname or ""
    address = socket.gethostbyname(host) if host == "localhost" else host
    if not ipaddress.ip_address(address).is_loopback:
        raise SystemExit(f"refusing {url}: this load test targets the loopback interface only")
    return host, parts.port or 80


def _client(host: str, port: int, body: bytes, deadline: float, tally: Tally) -> None:
    conn = http.client.HTTPConnection(host, port, timeout=30)
    headers = {"content-type": "application/json"}
    for _ in range(MAX_REQUESTS_PER_CLIENT):
        if time.monotonic() >= deadline:
            break
        start = time.perf_counter()
        try:
            conn.request("POST", "/api/torque", body=body, headers=headers)
            response = conn.getresponse()
            data = response.read()
            ok = response.status == 200 and b'"torque_Nm"' in data
            problem = "" if ok else f"status {response.status}: {data[:200]!r}"
        except (OSError, http.client.HTTPException) as exc:
            problem = f"{type(exc).__name__}: {exc}"
            conn.close()
            conn = http.client.HTTPConnection(host, port, timeout=30)
        elapsed = time.perf_counter() - start
        with tally.lock:
            tally.latencies.append(elapsed)
            if problem.startswith("status 503"):
                tally.busy += 1
            elif problem:
                tally.errors.append(problem)
    conn.close()


def run_load(url: str, clients: int, seconds: float) -> Tally:
    """``clients`` clients posting to ``/api/torque`` for ``seconds``; what they saw."""
    clients = min(clients, MAX_CLIENTS)
    seconds = min(seconds, MAX_SECONDS)
    host, port = _loopback(url)
    body = json.dumps(REQUEST).encode()
    tally = Tally()
    deadline = time.monotonic() + seconds
    threads = [
        threading.Thread(target=_client, args=(host, port, body, deadline, tally), daemon=True)
        for _ in range(clients)
    ]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=seconds + 60)
    return tally


def _chunks(size: int) -> Iterator[bytes]:
    block = b" " * 16384
    for _ in range(size // len(block)):
        yield block


def refusals(url: str) -> list[tuple[str, int, float]]:
    """Oversized and over-cap requests: (what, status, seconds until the answer)."""
    host, port = _loopback(url)
    size = 1 << 20
    out = []
    tries: list[tuple[str, object, dict[str, str]]] = [
        ("1 MiB body with Content-Length", b" " * size, {"content-type": "application/json"}),
        ("1 MiB body streamed in chunks", _chunks(size), {"content-type": "application/json"}),
        (
            "a million speeds",
            json.dumps({**REQUEST, "speed": "0..3000:1000000 rpm"}).encode(),
            {"content-type": "application/json"},
        ),
    ]
    for what, body, headers in tries:
        conn = http.client.HTTPConnection(host, port, timeout=30)
        start = time.perf_counter()
        try:
            if what.endswith("with Content-Length"):
                # The length alone must be refused, before any of the body is read: send
                # the head and wait for the answer (sending the body too raced the server's
                # answer and close, which the client then saw as a reset).
                conn.putrequest("POST", "/api/torque")
                for name, value in {**headers, "content-length": str(size)}.items():
                    conn.putheader(name, value)
                conn.endheaders()
            else:
                conn.request("POST", "/api/torque", body=body, headers=headers)  # type: ignore[arg-type]
            response = conn.getresponse()
            response.read()
            status = response.status
        except (BrokenPipeError, ConnectionResetError):
            # The server answered and closed while the body was still being sent.
            status = -1
        out.append((what, status, time.perf_counter() - start))
        conn.close()
    return out


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _start_server() -> tuple[subprocess.Popen[bytes], str]:
    port = _free_port()
    command = [sys.executable, "-m", "ballscrew", "serve", "--port", str(port)]
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    url = f"http://127.0.0.1:{port}"
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:
        try:
            conn = http.client.HTTPConnection("127.0.0.1", port, timeout=2)
            conn.request("GET", "/")
            if conn.getresponse().status == 200:
                conn.close()
                return process, url
        except OSError:
            time.sleep(0.2)
    process.kill()
    raise SystemExit("the server did not start")


def main() -> None:
    """Run the load test and print what it measured."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--clients", type=int, default=20)
    parser.add_argument("--seconds", type=float, default=30.0)
    parser.add_argument("--url", default=None, help="a running server (loopback only)")
    args = parser.parse_args()
    process, url = (None, args.url) if args.url else _start_server()
    try:
        tally = run_load(url, args.clients, args.seconds)
        lat = sorted(tally.latencies)
        n = len(lat)
        print(f"{min(args.clients, MAX_CLIENTS)} clients for {min(args.seconds, MAX_SECONDS):g} s "
              f"against {url}/api/torque (complete model, 50 speeds)")  # fmt: skip
        print(f"requests: {n}, errors: {len(tally.errors)}, 503 (busy): {tally.busy}, "
              f"throughput: {n / min(args.seconds, MAX_SECONDS):.1f} requests/s")  # fmt: skip
        if n:
            p95 = lat[min(n - 1, int(0.95 * n))]
            print(f"latency [ms]: median {statistics.median(lat) * 1e3:.1f}, "
                  f"p95 {p95 * 1e3:.1f}, max {lat[-1] * 1e3:.1f}")  # fmt: skip
        for problem in sorted(set(tally.errors))[:5]:
            print(f"error: {problem}")
        for what, status, seconds in refusals(url):
            shown = "connection closed by the server" if status == -1 else f"HTTP {status}"
            print(f"refused: {what}: {shown} after {seconds * 1e3:.1f} ms")
    finally:
        if process is not None:
            process.terminate()
            process.wait(timeout=30)


if __name__ == "__main__":
    main()
