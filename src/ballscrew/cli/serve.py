"""``ballscrew serve``: the web calculator on this machine (:mod:`ballscrew.web`)."""

from __future__ import annotations

import ipaddress

import click

from ..io.extras import require

__all__ = ["serve_command"]


def _is_loopback(host: str) -> bool:
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host.strip("[]")).is_loopback
    except ValueError:
        return False


@click.command("serve")
@click.option("--host", default="127.0.0.1", show_default=True,
              help="Address to listen on; loopback keeps it to this machine.")  # fmt: skip
@click.option("--port", default=8050, show_default=True, type=click.IntRange(0, 65535),
              help="Port to listen on (0: any free one).")  # fmt: skip
def serve_command(host: str, port: int) -> None:
    """Start the web calculator: one page and a JSON API (POST /api/torque).

    Open the address it prints in a browser; Ctrl-C stops it. It answers to
    the loopback names only (127.0.0.1, localhost) unless --host names
    another address, which other machines can then reach.

    \b
    Examples:
      ballscrew serve
      ballscrew serve --port 8080
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    require("web", "ballscrew serve")
    import uvicorn

    from ..web import create_app
    from ..web.app import LOOPBACK_HOSTS
    from ..web.server import server_config

    hosts = list(LOOPBACK_HOSTS)
    if not _is_loopback(host):
        hosts = ["*"] if host in ("0.0.0.0", "::") else [*hosts, host]
        click.echo(
            f"warning: listening on {host}: other machines can reach this calculator",
            err=True,
        )
    if port:
        shown = f"[{host}]" if ":" in host else host
        click.echo(f"ballscrew calculator on http://{shown}:{port}/ (Ctrl-C to stop)", err=True)
    # log_level info: uvicorn says where it listens (the port, when 0 was asked for).
    config = server_config(create_app(allowed_hosts=hosts), host=host, port=port,
                           log_level="info")  # fmt: skip
    uvicorn.Server(config).run()
