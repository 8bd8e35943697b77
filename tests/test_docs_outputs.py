"""The printed outputs the docs show are what the commands print.

Sybil runs the docs' ``sh`` blocks but only checks that they exit with status 0; the
``text`` block after a command, the output it shows, is not compared (a table's
centred title and the terminal's width would make a line-by-line check brittle). So
a model change could leave a page quoting numbers the command no longer prints. Here
the quick, deterministic examples (each under about 3 s of CPU) are run in-process in
a folder holding the page's ``% write:`` files, and:

- every line of the ``text`` block after the command must be a line of the output
  (standard output and error, leading and trailing spaces ignored; a line with
  ``...`` is the page's abridgement and is skipped; the block may show a part);
- where a page transcribes a table into Markdown, or quotes a number in its prose,
  the cells and numbers are compared to the printed ones at the printed digits.

A failure names the page: re-run the command and update the block and the prose
after it.
"""

from __future__ import annotations

import re
import shlex
from pathlib import Path

import pytest

from cli_runner import run
from docs_blocks import WRITE

ROOT = Path(__file__).resolve().parents[1]
FENCE = re.compile(
    r"^```(?P<lang>[a-z]*)[ \t]*\n(?P<body>.*?)^```[ \t]*$", re.MULTILINE | re.DOTALL
)


def _page(name: str) -> str:
    return (ROOT / name).read_text("utf-8")


@pytest.fixture
def folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A folder with the pages' ``% write:`` files and links to examples/ and src/."""
    for page in [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]:
        for match in WRITE.finditer(page.read_text("utf-8")):
            (tmp_path / (match["name"] or match["hname"])).write_text(match["body"], "utf-8")
    for name in ("examples", "src"):
        (tmp_path / name).symlink_to(ROOT / name)
    monkeypatch.chdir(tmp_path)
    # Wide enough that no table cell wraps (check's table with its source column).
    monkeypatch.setenv("COLUMNS", "250")
    return tmp_path


def _args(command: str) -> list[str]:
    """The arguments of a docs command (``ballscrew ...``, backslash continuations)."""
    words = shlex.split(command.replace("\\\n", " "))
    assert words[0] == "ballscrew", command
    return words[1:]


def _shown_after(page: str, command: str) -> str:
    """The body of the first ``text`` block after the ``sh`` block that runs ``command``."""
    blocks = list(FENCE.finditer(_page(page)))
    for i, block in enumerate(blocks):
        if block["lang"] == "sh" and block["body"].strip() == command.strip():
            for later in blocks[i + 1 :]:
                if later["lang"] == "sh":
                    break
                if later["lang"] == "text":
                    return later["body"]
    raise AssertionError(f"{page}: no text block after the command {command!r}")


def _printed(command: str, capsys: pytest.CaptureFixture[str]) -> str:
    code, out, err = run(_args(command), capsys)
    assert code == 0, err
    return out + err


def _assert_block_printed(page: str, command: str, printed: str) -> None:
    lines = {line.strip() for line in printed.splitlines()}
    missing = [
        line.strip()
        for line in _shown_after(page, command).splitlines()
        if line.strip() and "..." not in line and line.strip() not in lines
    ]
    assert not missing, (
        f"{page}: the block after `{command.splitlines()[0]}` shows lines the command no "
        f"longer prints (re-run it and update the block and its prose): {missing}"
    )


# (page, the command exactly as its sh block holds it)
BLOCKS = [
    (
        "docs/calibration-and-control.md",
        "ballscrew fit --case screw.toml --measured run.csv --free preload,ball_train_constant \\\n"
        "    --out fit --json fit.json",
    ),
    (
        "docs/calibration-and-control.md",
        "ballscrew fit --case screw.toml --measured run.csv "
        "--free preload,ball_train_constant,hysteresis_loss_factor",
    ),
    (
        "docs/calibration-and-control.md",
        'ballscrew export-friction --case screw.toml --form stribeck --temperature "20, 40 degC"',
    ),
    (
        "docs/calibration-and-control.md",
        "ballscrew export-friction --case screw.toml --form lugre --json -",
    ),
    (
        "docs/calibration-and-control.md",
        'ballscrew export-friction --case screw.toml --form table --temperature "20, 40 degC" \\\n'
        '    --speed "10..3000:4 rpm" --out friction_table.csv',
    ),
    (
        "docs/calibration-and-control.md",
        'ballscrew export-friction --form load-map --axial-load "-4..4:9 kN" \\\n'
        '    --temperature "20, 40 degC" --speed "10..3000:8 rpm" --out friction.mat',
    ),
    (
        "docs/calibration-and-control.md",
        "ballscrew monitor --case src/ballscrew/data/kamalzadeh_stage.toml \\\n"
        '  --measured examples/drag_torque_series.csv --threshold "50 %" --plot preload.png',
    ),
    (
        "docs/calibration-and-control.md",
        'ballscrew acceptance --case bnfn4010.toml --torque "0.80, 0.92, 0.86 N*m"',
    ),
    (
        "docs/calibration-and-control.md",
        "ballscrew export-friction --case screw.toml --measured run.csv --form coulomb-viscous",
    ),
]


@pytest.mark.parametrize(("page", "command"), BLOCKS, ids=lambda v: v.split("\n")[0][:60])
def test_the_block_after_a_command_is_what_it_prints(
    page: str, command: str, folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    _assert_block_printed(page, command, _printed(command, capsys))


def test_the_lookup_table_csv_is_the_one_shown(
    folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    page = "docs/calibration-and-control.md"
    _printed(
        'ballscrew export-friction --case screw.toml --form table --temperature "20, 40 degC" '
        '--speed "10..3000:4 rpm" --out friction_table.csv',
        capsys,
    )
    written = (folder / "friction_table.csv").read_text("utf-8").splitlines()
    text = _page(page)
    start = text.index("`friction_table.csv` (20 °C half")
    shown = next(m["body"] for m in FENCE.finditer(text, start)).splitlines()
    assert shown == written[: len(shown)], f"{page}: friction_table.csv's first rows changed"


def test_the_models_pages_six_models_warnings(
    folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    page = "docs/models.md"
    text = _page(page)
    case = text.index('title = "reference screw"')
    (folder / "ref.toml").write_text(text[case : text.index("```", case)], "utf-8")
    models = ("complete", "catalog", "harris-simplified", "olaru", "viscoelastic", "harris-full")
    command = "ballscrew torque --case ref.toml " + " ".join(f"--model {m}" for m in models)
    printed = _printed(command, capsys)
    start = text.index("### All six models on the reference screw")
    block = next(m["body"] for m in FENCE.finditer(text, start))
    lines = {line.strip() for line in printed.splitlines()}
    for line in block.splitlines():
        if line.strip() and "..." not in line:
            assert line.strip() in lines, f"{page}: the six models' warnings changed: {line}"
    # The loss budget's torques at 100 and 1000 rpm, as the terminal prints them (4 digits).
    assert re.search(r"complete │\s+100 │.*│\s+0\.5411 │", printed)
    assert re.search(r"complete │\s+1000 │.*│\s+0\.6082 │", printed)
    assert "| 100 | 0.5410681 |" in text and "| 1000 | 0.6082179 |" in text


def _check_rows(printed: str) -> dict[str, list[str]]:
    """The first nine cells of each row of ``ballscrew check``'s table, by criterion."""
    rows = {}
    for line in printed.splitlines():
        if line.startswith("│"):
            cells = [c.strip() for c in line.strip().strip("│").split("│")]
            if cells[0]:
                rows[cells[0]] = cells[:9]
    return rows


def test_the_guides_check_table_is_what_check_prints(
    folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    page = "docs/guide.md"
    command = (
        "ballscrew check --case examples/vertical_32x5.toml \\\n"
        '    --move "stroke=500 mm, feed=12 m/min, acceleration=3 m/s^2, force=1.5 kN, '
        'force_from=100 mm, force_to=400 mm, dwell=0.5 s"'
    )
    assert command in _page(page)
    printed = _check_rows(_printed(command, capsys))
    text = _page(page)
    start = text.index(command)
    table = text[start : text.index("How to read it:", start)]
    shown = [
        [c.strip() for c in line.strip().strip("|").split("|")]
        for line in table.splitlines()
        if line.startswith("| ") and not line.startswith("| criterion")
    ]
    assert len(shown) == len(printed) == 17
    for row in shown:
        assert printed.get(row[0]) == row, (
            f"{page}: the check row {row[0]!r} now prints {printed.get(row[0])}"
        )
    # The prose after it: the hour's warming and the lead error it quotes.
    assert "thermal lead error per 300 mm (P5)" in printed
    assert printed["thermal lead error per 300 mm (P5)"][1] == "36.04"
    assert "36 µm per 300 mm" in text


def test_the_readmes_worked_check(folder: Path, capsys: pytest.CaptureFixture[str]) -> None:
    readme = " ".join(_page("README.md").split())
    command = (
        'ballscrew check --case examples/vertical_32x5.toml --move "stroke=400 mm, '
        'feed=10 m/min, acceleration=2 m/s^2, force=1.5 kN"'
    )
    assert command.replace("ballscrew", "`ballscrew", 1) in readme
    rows = _check_rows(_printed(command, capsys))
    # criterion: (value as printed, the README's words with it)
    quoted = {
        "fatigue life L10": ("2917", "the life L10 is 2917 h"),
        "lift-off F_max / (2^1.5 F_pr)": ("2917", "the peak axial force, 2917 N"),
        "axis stiffness (least over the stroke, lifted off)": ("114.9", "(115 N/µm,"),
        "lost motion at reversal (most, lifted off)": ("3.052", "3.1 µm, 156 Hz"),
        "axial eigenfrequency (least, lifted off)": ("155.7", "156 Hz"),
        "thermal lead error per 300 mm (P5)": ("43.28", "43.3 µm per 300 mm"),
        "static safety C0a/F_max": ("20.43", "Static safety (20)"),
        "peak torque": ("7.697", "peak 7.7 of 18 N·m"),
    }
    for criterion, (value, words) in quoted.items():
        assert rows[criterion][1] == value, f"README: {criterion} now prints {rows[criterion]}"
        assert words in readme, f"README no longer says {words!r}"
    failing = (
        "fatigue life L10",
        "lift-off F_max / (2^1.5 F_pr)",
        "thermal lead error per 300 mm (P5)",
    )
    assert [rows[c][7] for c in failing] == ["100%", "100%", "99%"]
    assert "(P(NOT OK) 100 %, 100 % and 99 %)" in readme
    assert rows["d*n"][4:7] == ["91%", "91%-91%", "CHECK"]


def test_the_bundled_contour_examples_row(folder: Path, capsys: pytest.CaptureFixture[str]) -> None:
    page = "docs/positioning-accuracy.md"
    printed = _printed(
        'ballscrew contour --case examples/xy_table_32x10.toml --radius "50 mm" '
        '--feed "2 m/min"',  # both directions: the hysteresis H needs them
        capsys,
    )

    def number(pattern: str) -> float:
        found = re.search(pattern, printed)
        assert found, pattern
        return float(found[1])

    g = [number(r"CCW │\s+no │\s+([\d.]+) │"), number(r"CCW │\s+yes │\s+([\d.]+) │")]
    glitch = [
        number(r"CCW │\s+no │[^│]+│\s+(-?[\d.]+) /"),
        number(r"CCW │\s+yes │[^│]+│\s+(-?[\d.]+) /"),
    ]
    reduction = number(r"reduction by the compensation: ([\d.]+)")
    reversal = [number(r"without compensation: glitch (-?[\d.]+) um"),
                number(r"with compensation: glitch (-?[\d.]+) um")]  # fmt: skip
    hysteresis = number(r"circular hysteresis H ([\d.]+) um")
    row = (f"| 50 mm, 2 m/min | {g[0]:.1f} / {g[1]:.1f} | {abs(glitch[0]):.1f} / "
           f"{abs(glitch[1]):.1f} | {reduction:.1f} | {reversal[0]:.1f} / "
           f"{reversal[1]:.1f} |").replace("/ -", "/ −")  # fmt: skip
    text = _page(page)
    assert row in text, f"{page}: the example's row now reads {row}"
    assert f"at 50 mm and 2 m/min is {hysteresis:.1f} µm" in text
