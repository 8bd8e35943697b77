"""The web calculator driven in a real headless Chromium (Debian's, through Playwright).

A uvicorn server runs the application on a free loopback port in a thread;
the browser fills in the form, reads the charts and messages, downloads the
files and opens a case file, as a person would. The screenshots go to
``test-output/screenshots/`` (or ``$BALLSCREW_SCREENSHOTS``).

Without Chromium these tests are skipped on a developer's machine and fail on
CI (``CI`` set), where ``make test`` installs it.
"""

from __future__ import annotations

import csv
import io
import json
import os
import statistics
import time
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

from ballscrew.chain import friction_torque
from ballscrew.io.case import parse_case
from browser import CHROMIUM, chromium
from cli_runner import run
from shared import DATA, ROOT, reference_case_toml
from web_server import running_server

SHOTS = Path(os.environ.get("BALLSCREW_SCREENSHOTS", ROOT / "test-output" / "screenshots"))

if CHROMIUM is None and not os.environ.get("CI"):
    pytest.skip(
        "no chromium on this machine (make test installs Debian's); on CI these tests run",
        allow_module_level=True,
    )

sync_api = pytest.importorskip("playwright.sync_api")

# The page's defaults (templates/index.html), written as a case file.
DEFAULT_CASE = reference_case_toml("ball screw case", speed="10..3000:50 rpm", axial_load="1 kN")


@pytest.fixture(scope="module")
def base_url() -> Iterator[str]:
    with running_server() as url:
        yield url


@pytest.fixture(scope="module")
def browser() -> Iterator[sync_api.Browser]:
    with chromium() as b:
        yield b


@pytest.fixture
def page(browser: sync_api.Browser, base_url: str) -> Iterator[sync_api.Page]:
    context = browser.new_context(viewport={"width": 1280, "height": 900}, accept_downloads=True)
    pg = context.new_page()
    errors: list[str] = []
    pg.on("pageerror", lambda exc: errors.append(str(exc)))
    pg.goto(base_url)
    wait_revision(pg, 0)
    yield pg
    context.close()
    assert errors == [], errors  # no script error on the page


def revision(pg: sync_api.Page) -> int:
    return int(pg.get_attribute("body", "data-revision") or 0)


def wait_revision(pg: sync_api.Page, after: int, timeout: float = 10.0) -> int:
    """Wait until the page has shown results newer than revision ``after``."""
    deadline = time.monotonic() + timeout
    while (now := revision(pg)) <= after:
        assert time.monotonic() < deadline, f"no new results after revision {after}"
        pg.wait_for_timeout(20)
    return now


def settle(pg: sync_api.Page) -> int:
    """Wait until no request is pending and the results shown are the latest."""
    last = revision(pg)
    while True:
        pg.wait_for_timeout(400)  # longer than the page's 120 ms debounce plus a compute
        now = revision(pg)
        if now == last and pg.text_content("#status") != "computing...":
            return now
        last = now


def download(pg: sync_api.Page, button: str) -> str:
    with pg.expect_download() as info:
        pg.click(button)
    return Path(info.value.path()).read_text(encoding="utf-8")


def curve(pg: sync_api.Page, model: str) -> str:
    return pg.get_attribute(f'#chart_torque polyline[data-series="{model}"]', "points") or ""


def test_fill_in_a_screw_and_see_the_plot_update(page: sync_api.Page) -> None:
    before = curve(page, "complete")
    assert before.count(",") == 50  # one vertex per speed of the default grid
    page.check('input[name="screw_mode"][value="dimensions"]')
    for field, value in (("pitch_diameter", "32"), ("lead", "20"), ("ball_diameter", "3.969")):
        page.fill(f"#{field}", value)
    page.wait_for_selector("text=ball centre diameter 32 mm, lead 20 mm, balls 3.969 mm")
    settle(page)
    after = curve(page, "complete")
    assert after and after != before
    # How long the page takes from a change to new charts (debounce included):
    # the issue asks for under half a second with the closed-form models.
    latencies = []
    for temperature in ("20", "30", "50", "60", "40"):
        rev = revision(page)
        page.fill("#temperature", temperature)
        wait_revision(page, rev)
        latencies.append(int(page.get_attribute("body", "data-update-ms") or 0))
    print(f"page update latency [ms]: {latencies}")
    assert statistics.median(latencies) < 500, latencies


def test_a_bad_value_shows_the_command_lines_message_beside_its_field(
    page: sync_api.Page, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    page.check('input[name="screw_mode"][value="dimensions"]')
    settle(page)
    good_case = download(page, "#download_toml")
    page.fill("#lead", "-10")
    box = page.wait_for_selector('.field.invalid[data-field="screw.lead"] .error')
    assert box is not None
    shown = box.text_content()
    # The command line, given the same case with that lead:
    assert 'lead = "10 mm"' in good_case
    path = tmp_path / "bad.toml"
    path.write_text(good_case.replace('lead = "10 mm"', 'lead = "-10 mm"'), encoding="utf-8")
    code, _, err = run(["torque", "--case", str(path)], capsys)
    assert code == 2
    assert shown == err.strip().removeprefix("error: ")
    assert shown.startswith("screw.lead = '-10 mm' is not allowed")  # as typed
    assert page.is_hidden("#general_error")
    assert "stale" in (page.get_attribute("#results", "class") or "")
    # Corrected, the message goes and the results come back.
    rev = revision(page)
    page.fill("#lead", "10")
    wait_revision(page, rev)
    assert page.query_selector(".field.invalid") is None


def test_the_downloaded_csv_is_the_librarys_result(page: sync_api.Page) -> None:
    text = download(page, "#download_csv")
    rows = list(csv.DictReader(io.StringIO(text)))
    case = parse_case(DEFAULT_CASE)
    expected = friction_torque(
        case.screw,
        case.lubricant,
        speed=case.speed,
        temperature=40.0,
        axial_load=1000.0,
        model="complete",
    )
    complete = [r for r in rows if r["model"] == "complete"]
    # The CSV's digits (docs/guide.md, "Numbers in outputs"): speeds 6 significant
    # digits, results 4; each within half a unit of its last digit.
    np.testing.assert_allclose(
        [float(r["speed [rpm]"]) for r in complete], np.linspace(10, 3000, 50), rtol=5e-6
    )
    np.testing.assert_allclose(
        [float(r["torque [N*m]"]) for r in complete], expected.total, rtol=5e-4
    )
    np.testing.assert_allclose(
        [float(r["efficiency [-]"]) for r in complete], expected.efficiency, rtol=5e-4
    )
    assert {r["temperature [degC]"] for r in rows} == {"40"}
    assert {r["axial load [N]"] for r in rows} == {"1000"}
    assert {r["model"] for r in rows} == {"complete", "catalog"}
    # The level a maker accepts: at 100 rpm within THK's tolerance of the catalogue drag
    # torque (grade C3, +-35 % at 0.4-0.6 N*m), the catalogue rule taken at no axial load.
    rule = friction_torque(
        case.screw, case.lubricant, speed=10.472, temperature=40.0, axial_load=0.0,
        model="catalog",
    ).total  # fmt: skip
    at_100 = np.interp(100.0, np.linspace(10, 3000, 50), expected.total)
    assert abs(at_100 / rule - 1.0) < 0.35


def test_the_axis_check_on_the_page_is_the_commands(
    page: sync_api.Page, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # The page's defaults (the move is on): its verdict table against `ballscrew check`.
    settle(page)
    path = tmp_path / "case.toml"
    path.write_text(download(page, "#download_toml"), encoding="utf-8")
    move = "stroke=300 mm, feed=15 m/min, acceleration=2 m/s**2"
    code, text, err = run(["check", "--case", str(path), "--move", move, "--json", "-"], capsys)
    assert code == 0, err
    criteria = json.loads(text)["criteria"]
    rows = page.query_selector_all("#check_table tr.verdict")
    assert [r.get_attribute("data-verdict") for r in rows] == [c["verdict"] for c in criteria]
    assert [r.query_selector("th").text_content() for r in rows] == [c["name"] for c in criteria]
    assert (page.text_content("#check_verdict") or "").startswith(
        f"verdict: {json.loads(text)['verdict']}"
    )


def test_open_a_case_file(
    page: sync_api.Page, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    small = DATA / "small_case.toml"
    rev = revision(page)
    page.set_input_files("#upload", str(small))
    page.wait_for_selector("text=small test case:")
    wait_revision(page, rev)
    settle(page)
    assert page.input_value("#pitch_diameter") == "32"
    assert "kept as the file gives them" in (page.text_content("#upload_notice") or "")
    shown_csv = download(page, "#download_csv")
    shown_case = download(page, "#download_toml")
    # What the page shows for the file is what the command line computes from it.
    out = tmp_path / "cli.csv"
    args = ["torque", "--case", str(small), "--model", "complete", "--model", "catalog"]
    code, _, err = run([*args, "--csv", str(out)], capsys)
    assert code == 0, err
    assert shown_csv == out.read_text(encoding="utf-8")
    # The values the file marks as assumed keep their reasons in the case file offered.
    assert 'assumed = "typical nominal diameter' in shown_case
    assert parse_case(shown_case).screw == parse_case(small.read_text("utf-8")).screw


def test_screenshots_at_desktop_and_phone_widths(browser: sync_api.Browser, base_url: str) -> None:
    SHOTS.mkdir(parents=True, exist_ok=True)
    for name, width, height in (("desktop", 1280, 900), ("phone", 390, 844)):
        context = browser.new_context(viewport={"width": width, "height": height})
        pg = context.new_page()
        pg.goto(base_url)
        wait_revision(pg, 0)
        settle(pg)
        # Nothing wider than the screen: no sideways scrolling on a phone.
        assert pg.evaluate("document.documentElement.scrollWidth") <= width
        pg.screenshot(path=str(SHOTS / f"web-{name}.png"), full_page=True)
        context.close()
    assert (SHOTS / "web-desktop.png").stat().st_size > 10_000


def test_the_circular_test_on_the_page_draws_its_polar_plot(page: sync_api.Page) -> None:
    # The page's defaults (the move is on, so the axis has its mass): the button asks
    # /api/contour and draws the two runs about the nominal circle.
    settle(page)
    page.fill("#contour_radius", "5 mm")
    page.click("#contour_run")
    # (the page's security policy allows no evaluated script: wait on the element)
    page.locator("#chart_contour polygon").nth(1).wait_for(timeout=60_000)
    assert page.locator("#chart_contour polygon").count() == 2
    summary = page.text_content("#contour_summary") or ""
    assert summary.startswith("G ") and "with compensation" in summary


def test_choose_a_screw_lists_the_recommendation_first_with_why(page: sync_api.Page) -> None:
    # The page's defaults (a back-and-forth move, the 40 mm HIWIN nuts of 10 to 20 mm lead at
    # a light preload): the button asks /api/select and lists the recommendation first, the
    # rest of the front and the closest rejected nuts with what fails them.
    pytest.importorskip("pymoo")
    settle(page)
    page.click("#select_run")
    page.locator("#select_table tr[data-candidate]").first.wait_for(timeout=60_000)
    rows = page.locator("#select_table tr[data-candidate]")
    first = rows.first.locator("td")
    assert first.nth(1).text_content() == "recommended"
    assert (first.nth(0).text_content() or "").startswith("HIWIN R40-")
    reason = page.text_content("#select_reason") or ""
    assert reason.startswith("Recommended: HIWIN R40-") and "Why: " in reason
    summary = page.text_content("#select_summary") or ""
    assert "candidates" in summary and "on the front over energy, life" in summary
    page.locator("#select_section").screenshot(path=str(SHOTS / "web-select.png"))
    # A filter no nut passes: the server's message, naming the closest nuts.
    page.fill("#select_diameter", "90..100 mm")
    page.click("#select_run")
    page.locator("#select_summary", has_text="closest").wait_for(timeout=60_000)
    assert page.locator("#select_table tr").count() == 0


def test_imperial_results_on_the_page_are_the_commands(
    page: sync_api.Page, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # An American user: results in imperial, a load typed in pound-force with its unit.
    rev = settle(page)
    page.select_option("#units", "imperial")
    rev = wait_revision(page, rev)
    page.fill("#axial_load", "200 lbf")  # the unit typed overrides the list beside it
    page.wait_for_selector("text=and 200 lbf")
    settle(page)
    assert page.url.endswith("/?units=imperial")  # kept in the address, to share
    assert page.get_attribute("body", "data-units") == "imperial"
    assert page.query_selector(".field.invalid") is None
    assert "lead 0.3937 in" in (page.text_content("#summary") or "")  # 10 mm
    caption = page.text_content("#budget_caption") or ""
    assert caption.endswith("at 104 °F and 200 lbf"), caption  # 40 degC
    labels = page.eval_on_selector_all("#chart_torque text.label", "e => e.map(x => x.textContent)")
    assert "friction torque [lbf·in]" in labels
    # The loss budget's total at the first speed against `ballscrew torque --units imperial`.
    path = tmp_path / "case.toml"
    path.write_text(download(page, "#download_toml"), encoding="utf-8")
    code, out, err = run(["torque", "--case", str(path), "--model", "complete", "--speed",
                          "10 rpm", "--units", "imperial", "--table", "full"], capsys)  # fmt: skip
    assert code == 0, err
    row = next(line for line in out.splitlines() if line.startswith("│ complete"))
    cells = [c.strip() for c in row.strip("│").split("│")]
    assert cells[3] == "200"  # axial load [lbf]
    total = page.text_content("#budget_table tr.total td:nth-child(2)") or ""
    assert total.endswith(" lbf·in"), total
    # Both print 4 significant digits: each rounding is within 5e-4 of the value.
    assert float(total.split()[0]) == pytest.approx(float(cells[4]), rel=1e-3)
    # Opened again from its address, the page shows imperial from the start.
    again = page.context.new_page()
    again.goto(page.url)
    wait_revision(again, 0)
    assert again.eval_on_selector("#units", "e => e.value") == "imperial"
    assert "lbf·in" in (again.text_content("#energy_table") or "")


def test_a_case_files_output_units_chooses_the_pages(page: sync_api.Page, tmp_path: Path) -> None:
    path = tmp_path / "imperial.toml"
    path.write_text(DEFAULT_CASE + '\n[output]\nunits = "imperial"\n', encoding="utf-8")
    rev = settle(page)
    page.set_input_files("#upload", str(path))
    wait_revision(page, rev)
    settle(page)
    assert page.eval_on_selector("#units", "e => e.value") == "imperial"
    assert page.url.endswith("/?units=imperial")
    assert "lbf·in" in (page.text_content("#budget_table") or "")
    # The case file says imperial: the command prints it without a --units of its own.
    assert "--units" not in (page.text_content("#commands") or "")
    rev = revision(page)
    page.select_option("#units", "si")  # the page's choice wins, as --units does
    wait_revision(page, rev)
    settle(page)
    assert "/?" not in page.url
    assert "--units si" in (page.text_content("#commands") or "")
    assert "N·m" in (page.text_content("#budget_table") or "")
