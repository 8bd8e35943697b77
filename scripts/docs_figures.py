"""Draw the pictures of the README and the docs from the current version (``make docs``).

    .venv/bin/python scripts/docs_figures.py [--only NAME ...]

The documentation build (docs/conf.py) runs this before it reads the pages, so that every
picture in ``docs/img/`` shows what this version computes and says which version drew it:

- ``web-calculator.png`` and ``web-program.png``: the web calculator (``ballscrew serve``)
  in Chromium, driven by Playwright (Debian's ``/usr/bin/chromium``, as the browser tests
  launch it), the whole page at 1280 px and its part-program section after a run; the page
  prints the version under its title;
- ``friction_signs.png``: the sign conventions of the friction export
  (scripts/friction_sign_figure.py);
- ``monitor_example.png``: the preload read from a drag-torque series, its trend and the
  50 % crossing (``ballscrew monitor``);
- ``coverage_reliability.png``: the reliability diagram of the check's P(NOT OK) on
  synthetic cases with a known truth (scripts/coverage_figure.py).

Each PNG carries ``Software = ballscrew VERSION`` in its metadata (tests/test_docs_figures.py
checks it against the package's version); the figures also print it in a corner.
"""

from __future__ import annotations

import argparse
import io
import shutil
import sys
from collections.abc import Callable
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
IMG = ROOT / "docs" / "img"
sys.path.insert(0, str(ROOT / "tests"))  # the test suite's loopback server (web_server.py)
sys.path.insert(0, str(ROOT / "scripts"))

from ballscrew import __version__  # noqa: E402 - after the paths are set

SOFTWARE = f"ballscrew {__version__}"
CHROMIUM_ARGS = [
    "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
]  # fmt: skip


def _save_png(data: bytes, name: str) -> None:
    """Write PNG bytes to docs/img/NAME with the version in its metadata, atomically."""
    from PIL import Image, PngImagePlugin

    from ballscrew.io.files import atomic_write

    info = PngImagePlugin.PngInfo()
    info.add_text("Software", SOFTWARE)
    out = io.BytesIO()
    with Image.open(io.BytesIO(data)) as image:
        image.save(out, format="PNG", pnginfo=info, optimize=True)
    atomic_write(IMG / name, out.getvalue())


def _figure_png(fig: object) -> bytes:
    from matplotlib.figure import Figure

    assert isinstance(fig, Figure)
    fig.text(0.995, 0.005, SOFTWARE, ha="right", va="bottom", fontsize=7, color="0.45")
    out = io.BytesIO()
    fig.savefig(out, format="png", dpi=120, metadata={"Software": SOFTWARE})
    return out.getvalue()


def friction_signs() -> None:
    """docs/img/friction_signs.png."""
    import friction_sign_figure

    _save_png(_figure_png(friction_sign_figure.draw()), "friction_signs.png")


def monitor_example() -> None:
    """docs/img/monitor_example.png: examples/drag_torque_series.csv, threshold 50 %."""
    import warnings

    from ballscrew.errors import BallScrewValidityWarning
    from ballscrew.fit.monitor import run_monitor
    from ballscrew.io.case import load_case
    from ballscrew.io.series import read_series
    from ballscrew.report.monitor import monitor_figure

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", BallScrewValidityWarning)
        case = load_case(None)
        series = read_series(ROOT / "examples" / "drag_torque_series.csv", case.screw)
        result = run_monitor(case, series, limit="50 %")
    _save_png(_figure_png(monitor_figure(result)), "monitor_example.png")


def coverage_reliability() -> None:
    """docs/img/coverage_reliability.png: the check's P(NOT OK) against the known truth."""
    import coverage_figure

    _save_png(_figure_png(coverage_figure.draw()), "coverage_reliability.png")


def web_pages() -> None:
    """docs/img/web-calculator.png and docs/img/web-program.png, the page in Chromium."""
    from playwright.sync_api import sync_playwright

    from web_server import running_server

    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None:
        raise SystemExit("docs_figures: no chromium to draw the web pages (apt install chromium)")
    with running_server() as url, sync_playwright() as p:
        browser = p.chromium.launch(executable_path=chromium, headless=True, args=CHROMIUM_ARGS)
        page = browser.new_page(viewport={"width": 1280, "height": 900})
        page.goto(url)
        # Generous waits: on a loaded machine the workers warm up and compute slowly.
        page.set_default_timeout(180_000)
        page.wait_for_selector("body[data-revision]:not([data-revision='0'])")
        page.wait_for_timeout(600)  # the charts' last drawing after the first results
        shown = page.text_content("body") or ""
        if SOFTWARE not in shown:
            raise SystemExit(f"docs_figures: the page does not show {SOFTWARE!r}")
        # The status line's timings change from run to run: left out of the picture, so that
        # a rebuild redraws the same bytes.
        page.evaluate("""() => { const s = document.getElementById('status');
            s.textContent = s.textContent.replace(/: computed in .*$/, ''); }""")
        _save_png(page.screenshot(full_page=True), "web-calculator.png")
        page.click("#program_run")
        page.wait_for_selector('#program_table tr[data-quantity="screw friction [J]"]')
        page.wait_for_timeout(300)
        _save_png(page.locator("#program_section").screenshot(), "web-program.png")
        browser.close()


FIGURES: dict[str, Callable[[], None]] = {
    "friction_signs": friction_signs,
    "monitor_example": monitor_example,
    "coverage": coverage_reliability,
    "web": web_pages,
}


def main(argv: list[str] | None = None) -> None:
    """Draw the figures named (all by default)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", nargs="*", choices=sorted(FIGURES), default=sorted(FIGURES))
    args = parser.parse_args(argv)
    for name in args.only:
        FIGURES[name]()
        print(f"docs_figures: {name} drawn ({SOFTWARE})")


if __name__ == "__main__":
    main()
