"""Case files written without reading the code: template, check, reference, errors."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from ballscrew import friction_torque
from ballscrew.errors import BallScrewInputError
from ballscrew.io.case import load_case, parse_case
from ballscrew.io.schema import SECTIONS, CaseFile, reference_markdown, reference_rows, template
from cli_runner import run
from shared import ROOT

DOCS = ROOT / "docs" / "case-files.md"


def test_template_round_trips_through_check_and_torque(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    file = tmp_path / "my_screw.toml"
    code, _, _ = run(["case", "--template", "--out", str(file)], capsys)
    assert code == 0 and file.exists()
    code, out, _ = run(["case", "--check", str(file)], capsys)
    assert code == 0 and "case file OK" in out
    assert "40 mm" in out and "2000 N" in out  # the template's examples, resolved
    csv_file = tmp_path / "t.csv"
    code, out, err = run(
        ["torque", "--case", str(file), "--speed", "100, 1000 rpm", "--csv", str(csv_file)],
        capsys,
    )
    assert code == 0, err
    # The same torque as the API on the same screw (the template's 40 x 10 mm example).
    case = load_case(file)
    api = friction_torque(
        case.screw, case.lubricant, speed=[100 * 0.10471975511965977], temperature=20.0
    )
    assert f"{float(api.total[0]):.4g}" in out  # the terminal's 4 significant digits


def test_every_schema_key_is_in_the_template_and_the_reference() -> None:
    text = template()
    table = reference_markdown()
    keys = [(name, key) for name, model in SECTIONS.items() for key in model.model_fields]
    keys += [("", key) for key in CaseFile.model_fields if key not in SECTIONS]
    assert len(reference_rows()) == len(keys)
    for _section, key in keys:
        assert f"{key} = " in text, key
        assert f"`{key}`" in table, key
    for row in reference_rows():
        assert row.description, row.key  # every key documented


def test_documentation_table_is_the_generated_one() -> None:
    # docs/case-files.md carries the table between markers; regenerate it with
    # `ballscrew case --reference` when the schema changes.
    text = DOCS.read_text(encoding="utf-8")
    start = text.index("<!-- reference:start -->\n") + len("<!-- reference:start -->\n")
    end = text.index("<!-- reference:end -->")
    assert text[start:end] == reference_markdown()


@pytest.mark.parametrize(
    "edit, field, words",
    [
        (("lead = ", "leed = "), "screw.leed", "did you mean screw.lead?"),
        (('name = "PAO ISO VG 68"', 'name = "my oil"\nnu40 = "68 cSt"'), "lubricant.density15",
         "missing: density15, nu100"),
        (('pitch_diameter = "40 mm"', "pitch_diameter = 40"), "screw.pitch_diameter",
         "bare number"),
        (('pitch_diameter = "40 mm"', 'pitch_diameter = "40 m"'), "screw.pitch_diameter",
         "looks like mm"),
    ],
)  # fmt: skip
def test_case_errors_name_the_key(edit: tuple[str, str], field: str, words: str) -> None:
    text = template().replace(*edit)
    with pytest.raises(BallScrewInputError) as info:
        parse_case(text)
    assert info.value.field == field
    assert words in str(info.value)


def test_a_machine_file_given_as_a_case_says_which_command_reads_it(
    capsys: pytest.CaptureFixture[str],
) -> None:
    # A newcomer's trial of 0.3.0 gave examples/machine_vmc.toml to `energy --case`: the
    # refusal named "machine = {...}" as a misspelt key.
    machine = ROOT / "examples" / "machine_vmc.toml"
    code, _, err = run(["energy", "--case", str(machine), "--move", "stroke=300 mm, "
                        "feed=30 m/min, acceleration=2 m/s^2"], capsys)  # fmt: skip
    assert code == 2 and "a machine file" in err and "ballscrew program" in err
    assert "--machine" in err and "check the spelling" not in err


def test_case_needs_exactly_one_command(capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = run(["case"], capsys)
    assert code == 2 and "exactly one" in err


def test_check_shows_the_axis_as_the_energy_command_will_use_it(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    base = (
        '[screw]\npitch_diameter = "32 mm"\nlead = "5 mm"\nball_diameter = "3.175 mm"\n'
        'preload = "1.2 kN"\n[lubricant]\nname = "mineral ISO VG 68"\n'
    )
    file = tmp_path / "z.toml"
    file.write_text(base, "utf-8")
    code, out, _ = run(["case", "--check", str(file)], capsys)
    assert code == 0 and "moving mass" not in out  # no [axis]: nothing to show
    file.write_text(
        base + '[axis]\nmoving_mass = "120 kg"\nincline = "90 deg"\nscrew_length = "800 mm"\n'
        'bearing_bore = "20 mm"\n',
        "utf-8",
    )
    code, out, _ = run(["case", "--check", str(file)], capsys)
    assert code == 0 and "case file OK" in out
    # pi 7850 kg/m^3 x 0.8 m x (0.032 m)^4 / 32 = 6.465e-4 kg m^2
    shown = re.search(r"0\.000646 kg\*m\^2 \(estimated\) \[(\d+)\]", out)
    assert shown and f"[{shown[1]}] a solid steel shaft of the pitch diameter over 800 mm" in out
    assert "120 kg" in out and "90 deg" in out and "SKF's simplified estimate" in out
    assert "none (critical speed not checked)" in out and "none (convection only)" in out
    # Given values are shown as given, in mm and SI.
    file.write_text(
        base + '[axis]\nmoving_mass = "120 kg"\nscrew_inertia = "1.5e-3 kg*m**2"\n'
        'bearing_span = "1 m"\nscrew_length = "1.2 m"\nmachine_resistance = "2 K/W"\n'
        'bearing_bore = "20 mm"\n',
        "utf-8",
    )
    code, out, _ = run(["case", "--check", str(file)], capsys)
    assert code == 0
    for shown in ("0.0015 kg*m^2", "bore 20 mm", "1000 mm, fixed-supported", "1200 mm",
                  "20 degC, 2 K/W"):  # fmt: skip
        assert shown in out, shown


def test_check_prints_each_field_once_within_100_columns_with_its_sources_as_notes(
    capsys: pytest.CaptureFixture[str],
) -> None:
    # A newcomer's trial of 0.3.0: the designation row showed the catalogue's citation, C_a
    # and C_0a were printed twice, and the table was about 190 columns wide.
    example = ROOT / "examples" / "xy_table_32x10.toml"
    code, out, err = run(["case", "--check", str(example)], capsys)  # 200 columns: a pipe
    assert code == 0, err
    lines = out.splitlines()
    table = [line for line in lines if line[:1] in "┏┃┡│└"]
    assert table and max(len(line) for line in table) <= 100
    rows = [[c.strip() for c in line.strip("│").split("│")] for line in table
            if line.startswith("│")]  # fmt: skip
    quantities = [(r[0], r[1]) for r in rows]
    assert len(quantities) == len(set(quantities)), quantities  # each field once
    by_name = {r[1]: r[2] for r in rows}
    notes = {int(m[1]): m[2] for m in (re.match(r"\[(\d+)\] (.*)", x) for x in lines) if m}
    number = re.compile(r"\[(\d+)\]$")
    assert sorted(notes) == list(range(1, len(notes) + 1))  # numbered from 1, each once
    # The designation as written in the file; its catalogue under the table.
    assert by_name["designation"].startswith("HIWIN R32-10K5-FDC")
    cited = notes[int(number.search(by_name["designation"])[1])]  # type: ignore[index]
    assert cited.startswith("HIWIN GmbH") and "Table 6.5" in cited
    # The catalogue's ratings (HIWIN's R32-10K5-FDC row: 56.4 and 144.8 kN), one note.
    assert by_name["dynamic load rating C_a"].startswith("56.4 kN")
    assert by_name["static load rating C_0a"].startswith("144.8 kN")
    ca, c0a = (number.search(by_name[k]) for k in ("dynamic load rating C_a",
                                                    "static load rating C_0a"))  # fmt: skip
    assert ca and c0a and ca[1] == c0a[1] and "catalogue row" in notes[int(ca[1])]


def test_each_numeric_key_states_its_si_unit_in_the_schema_and_its_example_reads_in_it() -> None:
    # The case file's SI units live in the schema (issue 33): every key io/case.py turns
    # into a number names its SI unit there, and the key's own example (written by hand
    # in the schema, e.g. "6.35 mm", "10.3 cSt", "1.2e-4 m/N" would fail) converts to it.
    from ballscrew.io.case import LUBRICANT_UNITS, SCREW_UNITS
    from ballscrew.io.schema import AxisSection, LubricantSection, ScrewSection, si_units
    from ballscrew.io.units import to_si

    assert si_units(ScrewSection) == SCREW_UNITS
    assert si_units(LubricantSection) == LUBRICANT_UNITS
    assert set(si_units(AxisSection, "thermal")) == {
        "screw_length", "nut_mass", "machine_resistance", "ambient",
    }  # fmt: skip
    checked = 0
    for section, model in SECTIONS.items():
        for key, info in model.model_fields.items():
            extra = info.json_schema_extra if isinstance(info.json_schema_extra, dict) else {}
            if "si" not in extra:
                continue
            example = extra["example"]
            if isinstance(example, str) and example.endswith("%"):
                example = float(example[:-1]) / 100.0  # a share, read as such by case.py
            value = to_si(f"{section}.{key}", example, extra["si"])
            assert value == value, key  # finite: not NaN
            checked += 1
    assert checked >= 40
