"""Malformed files, unwritable outputs, degenerate profiles: exit 2 naming the field (issue 28).

Each input here was an internal error (exit 1) or a hang in the attack lists of issue
28: a deeply nested TOML file (RecursionError), a key of 50 000 dotted parts (a minute
in the TOML parser), an output path under a file (FileExistsError) or where nothing can
be written (FileNotFoundError naming a temporary file), a profile of two data rows
(numpy's gradient), a missing or binary profile, a move of 1e30 m (numpy's 'maximum
allowed size exceeded') and a negative nu40 named as 'lubricant.kinematic_viscosity'.
"""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.io.case import MAX_TOML_DEPTH, parse_case, parse_toml
from ballscrew.io.schema import template
from cli_runner import run
from shared import SMALL_CASE

MOVE = "stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2"


def _error(capsys: pytest.CaptureFixture[str], args: list[str]) -> str:
    code, _, err = run(args, capsys)
    assert code == 2, err
    assert "internal error" not in err and "Traceback" not in err
    return err.strip().splitlines()[-1]


# ------------------------------------------------------------ TOML files


@pytest.mark.parametrize(
    ("text", "words"),
    [
        ("a = " + "[" * 100_000 + "]" * 100_000 + "\n", "nested at most 32 deep"),
        ("a = " + "{b = " * 5_000 + "1" + "}" * 5_000 + "\n", "nested at most 32 deep"),
        ("a = " + "[" * 40 + "]" * 40 + "\n", "nested at most 32 deep"),  # under the stack's
        (".".join(["a"] * 50_000) + " = 1\n", "fewer than 32 dotted parts"),
        ("[" + ".".join(['"a"'] * 40) + "]\n", "fewer than 32 dotted parts"),
        ("# " + "x" * 1_000_001 + "\n", "at most 1,000,000 characters"),
    ],
)
def test_toml_the_parser_cannot_take_is_refused_at_once(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], text: str, words: str
) -> None:
    start = time.perf_counter()
    with pytest.raises(BallScrewInputError) as info:
        parse_toml(text, "case")
    assert info.value.field == "case" and words in str(info.value)
    file = tmp_path / "bad.toml"
    file.write_text(text, "utf-8")
    for args in (
        ["case", "--check", str(file)],
        ["torque", "--case", str(file)],
        ["sweep", str(file), "--out", str(tmp_path / "s.zarr")],
    ):
        line = _error(capsys, args)
        assert line.startswith(f"error: {file} = ") and words in line, line
    assert time.perf_counter() - start < 10.0  # the dotted key took 67 s before


def test_toml_within_the_limits_is_read_as_ever() -> None:
    nested = "a = " + "[" * (MAX_TOML_DEPTH - 1) + "1" + "]" * (MAX_TOML_DEPTH - 1) + "\n"
    assert parse_toml(nested, "x")["a"]
    dotted = ".".join(["a"] * (MAX_TOML_DEPTH - 1)) + " = 1\n"
    assert parse_toml(dotted, "x")["a"]
    # Dots in strings, numbers and quoted sweep keys are not dotted keys.
    text = 'x = "1.2.3.4.5.6.7.8.9.10.11.12.13.14.15.16.17.18.19.20.21.22.23.24.25.26.27.28.29.30.31.32.33"\n"screw.preload" = "1.5 kN"\n'  # noqa: E501
    assert parse_toml(text, "x")["screw.preload"] == "1.5 kN"


def test_a_negative_nu40_is_named_as_the_user_wrote_it(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    own = 'name = "my oil"\nnu40 = "-68 cSt"\nnu100 = "10 cSt"\ndensity15 = "850 kg/m^3"'
    text = template().replace('name = "PAO ISO VG 68"', own, 1)
    with pytest.raises(BallScrewInputError) as info:
        parse_case(text)
    assert info.value.field == "lubricant.nu40"  # was lubricant.kinematic_viscosity
    file = tmp_path / "oil.toml"
    file.write_text(text, "utf-8")
    for command in ("case --check", "torque --case"):
        line = _error(capsys, [*command.split(), str(file)])
        assert line.startswith("error: lubricant.nu40 = "), line


# ------------------------------------------------------------ outputs


@pytest.fixture
def in_the_way(tmp_path: Path) -> Path:
    """A file where an output's folder would have to be."""
    file = tmp_path / "a-file"
    file.write_text("mine", "utf-8")
    return file


@pytest.mark.parametrize(
    ("args", "option"),
    [
        (["torque", "--speed", "100 rpm", "--csv", "{x}/t.csv"], "--csv"),
        (["torque", "--speed", "100 rpm", "--json", "{x}/t.json"], "--json"),
        (["energy", "--case", "{axis}", "--move", MOVE, "--json", "{x}/e.json"], "--json"),
        (["energy", "--case", "{axis}", "--move", MOVE, "--out", "{x}/e"], "--out"),
        (["case", "--template", "--out", "{x}/c.toml"], "--out"),
        (["sweep", "{sweep}", "--out", "{x}/s.zarr"], "--out"),
        (["validate", "--model", "catalog", "--out", "{x}/v"], "--out"),
        (["study", "--case", "{small}", "--out", "{x}/r"], "--out"),  # before it computes
        (["fit", "--case", "{small}", "--measured", "{measured}", "--free", "preload", "--json",
          "{x}/f.json"], "--json"),
        (["fit", "--case", "{small}", "--measured", "{measured}", "--free", "preload", "--out",
          "{x}/f"], "--out"),
    ],
)  # fmt: skip
def test_an_output_that_cannot_be_written_names_its_option_and_path(
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    in_the_way: Path,
    args: list[str],
    option: str,
) -> None:
    axis = tmp_path / "axis.toml"
    axis.write_text(template().replace("[axis]", '[axis]\nmoving_mass = "50 kg"', 1), "utf-8")
    sweep = tmp_path / "s.toml"
    sweep.write_text(f'case = "{SMALL_CASE.as_posix()}"\n[axes]\nspeed = "100 rpm"\n', "utf-8")
    measured = tmp_path / "m.csv"
    rows = "\n".join(f"{s},{0.3 + s * 1e-5}" for s in range(100, 3000, 300))
    measured.write_text(f"speed [rpm],torque [N*m]\n{rows}\n", "utf-8")
    names = {"x": in_the_way, "axis": axis, "sweep": sweep, "measured": measured,
             "small": SMALL_CASE}  # fmt: skip
    line = _error(capsys, [a.format(**names) for a in args])
    assert line.startswith(f"error: {option} = '{in_the_way}/") and "(File exists)" in line
    assert in_the_way.read_text("utf-8") == "mine"
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]  # no temporary left


def test_an_output_in_a_folder_that_does_not_exist_yet_is_written_there(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # The FileNotFoundError naming a temporary file: the folders are made now.
    out = tmp_path / "no" / "such" / "folder"
    code, _, err = run(["torque", "--speed", "100 rpm", "--csv", str(out / "t.csv"),
                        "--json", str(out / "t.json")], capsys)  # fmt: skip
    assert code == 0, err
    assert {p.name for p in out.iterdir()} == {"t.csv", "t.csv.meta.json", "t.json"}


# ------------------------------------------------------------ profiles and moves


@pytest.fixture
def axis_case(tmp_path: Path) -> Path:
    file = tmp_path / "axis.toml"
    file.write_text(template().replace("[axis]", '[axis]\nmoving_mass = "50 kg"', 1), "utf-8")
    return file


@pytest.mark.parametrize(
    ("content", "field", "words"),
    [
        (b"time [s],position [mm]\n0,0\n1,1\n", "{p}", "at least 3 data rows"),
        (b"time [s],speed [m/s]\n0,0\n1,0.1\n", "{p}", "at least 3 data rows"),
        (b"time [s],position [mm]\n0,0\n1,nan\n2,2\n3,3\n", "{p}: line 3, column position",
         "a finite number"),
        (b"time [s],position [furlongz]\n0,0\n1,1\n2,2\n", "{p}: header 'position [furlongz]'",
         "not a known unit"),
        (b"\xe6\x00\xff" * 100, "--profile", "a UTF-8 text file"),
        (None, "--profile", "a readable file (No such file or directory)"),
    ],
)  # fmt: skip
def test_a_profile_that_cannot_be_used_names_the_file_line_or_header(
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    axis_case: Path,
    content: bytes | None,
    field: str,
    words: str,
) -> None:
    profile = tmp_path / "profile.csv"
    if content is not None:
        profile.write_bytes(content)
    line = _error(capsys, ["energy", "--case", str(axis_case), "--profile", str(profile)])
    assert line.startswith(f"error: {field.format(p=profile)} = ") and words in line, line


@pytest.mark.parametrize(
    ("move", "field", "words"),
    [
        ("stroke=300 mm, feed=0 m/s, acceleration=2 m/s^2", "--move feed", "more than 0"),
        ("stroke=1e30 m, feed=1 m/s, acceleration=2 m/s^2", "--move, --cycles",
         "at most 5,000,000 samples"),
        # A decimal comma in a list the commas separate: refused, not read as force = 1 N.
        ("stroke=300 mm, feed=1 m/s, acceleration=2 m/s^2, force=1,2 kN", "--move force",
         "a decimal point"),
    ],
)  # fmt: skip
def test_a_move_that_cannot_be_sampled_is_refused_before_any_array_is_made(
    capsys: pytest.CaptureFixture[str], axis_case: Path, move: str, field: str, words: str
) -> None:
    start = time.perf_counter()
    line = _error(capsys, ["energy", "--case", str(axis_case), "--move", move])
    assert line.startswith(f"error: {field} = ") and words in line, line
    assert time.perf_counter() - start < 10.0


def test_many_cycles_of_a_short_move_are_refused_too(
    capsys: pytest.CaptureFixture[str], axis_case: Path
) -> None:
    line = _error(
        capsys, ["energy", "--case", str(axis_case), "--move", MOVE, "--cycles", "100000"]
    )
    assert line.startswith("error: --move, --cycles = '100000 cycle(s) of ")


@pytest.mark.parametrize(
    ("key", "field"),
    [
        ('moving_mass = "-5 kg"', "axis.moving_mass"),
        ("gear_ratio = 0", "axis.gear_ratio"),
        ('screw_length = "0 m"', "axis.screw_length"),
        ('machine_resistance = "-1 K/W"', "axis.machine_resistance"),
        ('ambient = "900 degC"', "axis.ambient"),
    ],
)
def test_case_check_refuses_the_axis_energy_refuses_naming_the_key(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], key: str, field: str
) -> None:
    # Before, case --check said OK for a negative moving mass that energy then refused
    # as 'moving_mass' (and took a screw length of 0).
    file = tmp_path / "axis.toml"
    file.write_text(template().replace("[axis]", f"[axis]\n{key}", 1), "utf-8")
    for args in (["case", "--check", str(file)],
                 ["energy", "--case", str(file), "--move", MOVE]):  # fmt: skip
        line = _error(capsys, args)
        assert line.startswith(f"error: {field} = "), line
