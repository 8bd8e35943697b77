"""Result tables as files a colleague can open, trust and trace: CSV and JSON.

A table of friction results is built once (:func:`result_rows`, long format:
one row per model and operating point, in user units) and written as

* CSV, long (one row per model and point, with the model's components) or
  wide (one row per point, one torque column per model), with a comma or,
  for spreadsheets in decimal-comma locales, a semicolon and decimal commas;
* JSON, with the rows and their provenance inline.

Every CSV has a ``.meta.json`` file beside it with the provenance
(:func:`provenance`): package version, the case as read, the resolved screw
and lubricant in SI, each model's parameters and reference, and the validity
warnings. Numbers are rounded at output only: a CSV cell to the significant
digits :func:`ballscrew.io.numbers.column_digits` gives its column (4 for
results, more for times, positions, speeds and temperatures). The JSON rows
carry the results at full precision (each float written so that it reads back
to the same float, as every ``--json`` of the package does: the guide's
"Numbers in outputs"), and the operating point to 12 significant digits: it is
an input converted back to the unit it was typed in, so 100 rpm reads 100, not
the 99.99999999999999 of the round trip through rad/s. The bytes are
reproducible (no time stamps).
"""

from __future__ import annotations

import csv
import dataclasses
import io
import json
import math
from collections.abc import Callable, Mapping, Sequence
from typing import Any, Protocol

import numpy as np

from .._version import __version__
from ..chain import FrictionResult
from ..io.case import Case
from ..io.numbers import column_digits, text
from ..kinematics import rad_s_to_rpm

__all__ = [
    "DIALECTS",
    "INPUT_HEADER",
    "csv_bytes",
    "csv_text",
    "input_rows",
    "json_text",
    "provenance",
    "result_json",
    "result_rows",
    "round_significant",
]

INPUT_DIGITS = 12
"""Significant digits of an operating point converted back to its user unit (rpm)."""

DIALECTS = ("comma", "semicolon-decimal-comma")
"""CSV flavours: ``comma`` (RFC 4180, decimal point) and ``semicolon-decimal-comma``
(semicolon separator and decimal comma, what spreadsheets in e.g. German or
French locales read as numbers)."""

POINT_KEYS = ("speed [rpm]", "temperature [degC]", "axial load [N]")


def round_significant(x: float, digits: int) -> float:
    """``x`` rounded to ``digits`` significant digits (finite values; others unchanged).

    >>> round_significant(99.99999999999999, 12), round_significant(0.123456789, 3)
    (100.0, 0.123)
    """
    if not math.isfinite(x) or x == 0.0:
        return float(x)
    return float(f"{x:.{digits}g}")


def result_rows(results: Mapping[str, FrictionResult]) -> list[dict[str, Any]]:
    """Long-format rows (model, point, torque, power, efficiency, components), user units.

    The results at full precision; the point (an input) to :data:`INPUT_DIGITS`.
    """
    rows: list[dict[str, Any]] = []
    for name, r in results.items():
        w, t, f = (
            np.ravel(np.broadcast_to(x, r.total.shape))
            for x in (r.speed, r.temperature, r.axial_load)
        )
        total, power, eff = (np.ravel(x) for x in (r.total, r.power_loss, r.efficiency))
        parts = {k: np.ravel(np.broadcast_to(v, r.total.shape)) for k, v in r.components.items()}
        for k in range(total.size):
            row: dict[str, Any] = {
                "model": name,
                "speed [rpm]": round_significant(float(rad_s_to_rpm(w[k])), INPUT_DIGITS),
                "temperature [degC]": round_significant(float(t[k]), INPUT_DIGITS),
                "axial load [N]": round_significant(float(f[k]), INPUT_DIGITS),
                "torque [N*m]": float(total[k]),
                "power loss [W]": float(power[k]),
                "efficiency [-]": float(eff[k]),
            }
            for part, values in parts.items():
                row[f"{part} [N*m]"] = float(values[k])
            rows.append(row)
    return rows


def _wide(rows: Sequence[Mapping[str, Any]]) -> list[dict[str, Any]]:
    """One row per operating point, one torque column per model."""
    models = list(dict.fromkeys(str(r["model"]) for r in rows))
    points: dict[tuple[Any, ...], dict[str, Any]] = {}
    for r in rows:
        key = tuple(r[k] for k in POINT_KEYS)
        point = points.setdefault(key, {k: r[k] for k in POINT_KEYS})
        point[f"torque {r['model']} [N*m]"] = r["torque [N*m]"]
    columns = [*POINT_KEYS, *(f"torque {m} [N*m]" for m in models)]
    return [{c: p.get(c, "") for c in columns} for p in points.values()]


def csv_bytes(
    header: Sequence[str], rows: Sequence[Sequence[object]], *, digits: int | None = None
) -> bytes:
    r"""A header and rows as CSV (comma, ``\n`` line ends), UTF-8 bytes for a report file.

    Each number is rounded to its column's significant digits
    (:func:`ballscrew.io.numbers.column_digits`), or to ``digits`` if given.

    >>> csv_bytes(["a", "speed [rpm]", "torque [N*m]"], [[1, -3000.0000000000005, 0.302597903]])
    b'a,speed [rpm],torque [N*m]\n1,-3000,0.3026\n'
    """
    places = [column_digits(h) if digits is None else digits for h in header]
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(header)
    for row in rows:
        writer.writerow([_number(v, d) for v, d in zip(row, places, strict=False)]
                        + list(row[len(places):]))  # fmt: skip
    return buffer.getvalue().encode("utf-8")


def _number(value: object, digits: int) -> object:
    """A float (Python's or numpy's) as text to ``digits`` significant digits, others as given."""
    if isinstance(value, float | np.floating):
        return text(float(value), digits)
    return value


def csv_text(
    rows: Sequence[Mapping[str, Any]],
    *,
    layout: str = "long",
    dialect: str = "comma",
    digits: int | None = None,
) -> str:
    """The rows as CSV text; ``layout`` "long" or "wide", ``dialect`` one of :data:`DIALECTS`.

    Numbers to their column's significant digits
    (:func:`ballscrew.io.numbers.column_digits`), or to ``digits`` if given.
    """
    table = list(rows) if layout == "long" else _wide(rows)
    columns = list(dict.fromkeys(k for r in table for k in r))
    buffer = io.StringIO()
    separator = ";" if dialect == "semicolon-decimal-comma" else ","
    writer = csv.DictWriter(
        buffer, fieldnames=columns, lineterminator="\n", delimiter=separator, restval=""
    )
    writer.writeheader()
    for r in table:
        writer.writerow({
            k: _cell(v, dialect, column_digits(k) if digits is None else digits)
            for k, v in r.items()
        })  # fmt: skip
    return buffer.getvalue()


def _cell(value: Any, dialect: str, digits: int) -> Any:
    if isinstance(value, float | np.floating):
        shown = text(float(value), digits)
        return shown.replace(".", ",") if dialect == "semicolon-decimal-comma" else shown
    return value


def provenance(
    case: Case,
    results: Mapping[str, FrictionResult],
    command: Sequence[str] = (),
) -> dict[str, Any]:
    """What a result was computed from: package, case, screw, lubricant, models, warnings."""
    from ..friction import get_model

    screw = dataclasses.asdict(case.screw)
    oil = case.lubricant
    return {
        "ballscrew": __version__,
        "command": list(command),
        "units": "SI (m, N, Pa, Pa*s, m**2/s, kg/m**3, 1/Pa, rad, rad/s); temperatures in degC",
        "case": {
            "title": case.title,
            "assumptions": [dataclasses.asdict(a) for a in case.assumptions],
            "text": case.text,
            "values": case.input_values(),
        },
        "screw": screw,
        "lubricant": {
            "name": oil.name,
            "nu40": oil.nu40,
            "nu100": oil.nu100,
            "density15": oil.density15,
            "pressure_viscosity": oil.pressure_viscosity,
            "source": oil.source,
            "kind": oil.kind,
            "thickener": oil.thickener,
            "nlgi_grade": oil.nlgi_grade,
            "base_oil": oil.base_oil,
            "pour_point": oil.pour_point,
            "flash_point": oil.flash_point,
        },
        "models": {
            name: {
                "title": get_model(name).title,
                "reference": get_model(name).reference,
                "parameters": {k: _jsonable(v) for k, v in r.parameters.items()},
                "warnings": [dataclasses.asdict(issue) for issue in r.warnings],
            }
            for name, r in results.items()
        },
    }


INPUT_HEADER = ["key", "value (SI)", "unit", "source"]
"""The columns of a report's table of inputs (:func:`input_rows`)."""


def input_rows(values: Sequence[Mapping[str, Any]]) -> list[list[str]]:
    """A report's table of a case's inputs (:meth:`ballscrew.io.case.Case.input_values`).

    One row per key that has a value, or whose absence the run reads in a stated
    way; a value to :data:`~ballscrew.io.numbers.INPUT_DIGITS` digits, a list of
    more than three values as its count and span; the source followed by how the
    value was found.
    """
    from ..io.numbers import INPUT_DIGITS

    rows = []
    for v in values:
        value, how = v["value"], v.get("how", "")
        if value is None and not how:
            continue
        if value is None:
            shown = "-"
        elif isinstance(value, list) and len(value) > 3:
            shown = f"{len(value)} values, {text(min(value), INPUT_DIGITS)} to " \
                    f"{text(max(value), INPUT_DIGITS)}"  # fmt: skip
        elif isinstance(value, list):
            shown = ", ".join(text(x, INPUT_DIGITS) for x in value)
        else:
            shown = text(value, INPUT_DIGITS)
        rows.append([v["key"], shown, v.get("unit", ""), v["source"] + (f": {how}" if how else "")])
    return rows


def _jsonable(value: Any) -> Any:
    if isinstance(value, str | int | float | bool) or value is None:
        return value
    if isinstance(value, np.generic):
        return value.item()
    return repr(value)


def _map_nonfinite(obj: Any, replace: Callable[[float], Any]) -> Any:
    """A copy of nested mappings and lists with each non-finite float replaced."""
    if isinstance(obj, float) and not math.isfinite(obj):
        return replace(obj)
    if isinstance(obj, Mapping):
        return {str(k): _map_nonfinite(v, replace) for k, v in obj.items()}
    if isinstance(obj, list | tuple):
        return [_map_nonfinite(v, replace) for v in obj]
    return obj


def _clean(obj: Any) -> Any:
    """JSON-safe copy: non-finite numbers become the strings "inf", "-inf", "nan"."""
    return _map_nonfinite(obj, repr)


def finite_or_null(obj: Any) -> Any:
    """JSON-safe copy: non-finite numbers become None (JSON null); strict JSON has no NaN."""
    return _map_nonfinite(obj, lambda _: None)


def json_document(data: Any) -> str:
    """``data`` as strict JSON text, one item per line: non-finite numbers are null."""
    return json.dumps(finite_or_null(data), indent=1, ensure_ascii=False, allow_nan=False) + "\n"


def json_text(rows: Sequence[Mapping[str, Any]], meta: Mapping[str, Any]) -> str:
    """The rows and their provenance as one JSON document (strict JSON: no NaN)."""
    document = _clean({"provenance": meta, "rows": list(rows)})
    return json.dumps(document, indent=1, ensure_ascii=False, allow_nan=False) + "\n"


class _Result(Protocol):
    def as_dict(self) -> dict[str, Any]: ...


def result_json(result: _Result) -> str:
    """A command's result as its ``--json`` file: the package's version, then its :meth:`as_dict`.

    The version is the writer's to add, not each result's (strict JSON,
    non-finite numbers null: :func:`json_document`).
    """
    return json_document({"ballscrew": __version__, **result.as_dict()})
