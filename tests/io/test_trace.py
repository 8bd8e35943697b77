"""Drive traces: the CSV, scope exports read as written, errors naming line and column."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.io.trace import parse_mapping, parse_trace

ROWS = 30


def _table(sep: str = ",", decimal: str = ".") -> str:
    rows = [sep.join(f"{v}".replace(".", decimal) for v in (round(0.02 * k, 2),
                                                            round(0.5 * k, 3), round(0.1 * k, 2)))
            for k in range(ROWS)]  # fmt: skip
    return "\n".join(rows)


def test_units_in_the_header_are_converted_to_si() -> None:
    t = parse_trace("time [ms],X position [mm],X current [mA]\n" + _table())
    assert t.time[1] == pytest.approx(2e-5)  # 0.02 ms
    assert t.axes["X"].position[2] == pytest.approx(1e-3)  # 1.0 mm
    assert t.axes["X"].signal[3] == pytest.approx(3e-4)  # 0.3 mA
    assert t.axes["X"].kind == "current"


def test_semicolons_take_decimal_commas() -> None:
    t = parse_trace("time [s];Z position [mm];Z torque [N*m]\n" + _table(";", ","))
    assert t.axes["Z"].kind == "torque"
    assert t.axes["Z"].signal[5] == pytest.approx(0.5)


def test_a_halscope_log_is_read_as_written_with_the_channels_mapped() -> None:
    # LinuxCNC halscope's "Save log": the period, then name/value pairs on each line.
    lines = ["Sampling period is 1000000 ns ", ""]
    lines += [f"joint.0.motor-pos-fb {0.01 * k:+.14f} amp.0.current {0.1 * k:+.14f} "
              for k in range(ROWS)]  # fmt: skip
    names = parse_mapping("joint.0.motor-pos-fb=X position [mm]; amp.0.current=X current [A]")
    t = parse_trace("\n".join(lines), mapping=names)
    assert t.time[-1] == pytest.approx((ROWS - 1) * 1e-3)  # the index times 1 ms
    assert t.axes["X"].position[10] == pytest.approx(1e-4)
    with pytest.raises(BallScrewInputError, match="header"):
        parse_trace("\n".join(lines))  # unmapped: no time is named, no axis either


def test_a_scope_export_skips_its_metadata_and_stops_at_eof() -> None:
    # TwinCAT Scope-like: metadata lines above the channel table, times in ms, a last EOF.
    head = "Name;axis test\nStartTime;133000000000000000\n\nTime;X_ActPos;X_Cur;Spare\n"
    rows = [f"{20 * k};{0.5 * k:.1f};{0.1 * k:.2f};1".replace(".", ",") for k in range(ROWS)]
    text = head + "\n".join(rows) + "\nEOF\n"
    names = parse_mapping("Time=time [ms];X_ActPos=X position [mm];X_Cur=X current [A]")
    t = parse_trace(text, mapping=names)
    assert t.time[1] == pytest.approx(0.02)
    assert t.axes["X"].position[3] == pytest.approx(1.5e-3)  # decimal comma: 1,5 mm
    assert t.axes["X"].position.size == ROWS
    assert any("Spare" in note for note in t.notes)


@pytest.mark.parametrize(
    ("header", "body", "match"),
    [
        (
            "time [s],X position [mm],X current [A]",
            "0.0,0,0\n0.02,x,0",
            "line 3, column 'X position",
        ),
        ("time [s],X position [mm],X current [%]", "", "unit of current"),
        ("time [s],X position [mm]", "", "exactly one of current"),
        ("time [s],X position [mm],X current [A],X torque [N*m]", "", "exactly one of current"),
        ("time [s],Q position [mm],Q current [A]", "", "a linear axis"),
        ("X position [mm],X current [A],speed", "", "time column"),
    ],
)
def test_errors_name_the_line_and_the_column(header: str, body: str, match: str) -> None:
    rest = "\n".join(f"{0.02 * k:.2f},{k},{k},{k}" for k in range(2, ROWS))
    with pytest.raises(BallScrewInputError, match=match):
        parse_trace(header + "\n" + (body or "0.0,0,0,0\n0.02,1,1,1") + "\n" + rest)


def test_times_must_increase() -> None:
    rows = [f"{0.02 * k:.2f},{k},{k}" for k in range(ROWS)]
    rows[7] = "0.10,7,7"
    with pytest.raises(BallScrewInputError, match=r"line 9.*times increasing"):
        parse_trace("time [s],X position [mm],X current [A]\n" + "\n".join(rows))


def test_too_short_a_trace_is_refused() -> None:
    with pytest.raises(BallScrewInputError, match="at least 20"):
        parse_trace("time [s],X position [mm],X current [A]\n0,0,0\n0.02,1,1\n0.04,2,2")


def test_a_mapping_names_a_column_of_the_file() -> None:
    with pytest.raises(BallScrewInputError, match="--map nope"):
        parse_trace("time [s],X position [mm],X current [A]\n" + _table(),
                    mapping={"nope": "X torque [N*m]"})  # fmt: skip
    with pytest.raises(BallScrewInputError, match="--map"):
        parse_mapping("just a name")
    assert math.isfinite(float(np.sum(parse_trace("time [s],X position [mm],X power [kW]\n"
                                                   + _table()).axes["X"].signal)))  # fmt: skip
