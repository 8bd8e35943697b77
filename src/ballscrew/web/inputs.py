"""What a web request may carry, and how it becomes a case: limits, refusals, parsing.

A request's fields are turned into a case file's TOML text and read by
:func:`ballscrew.io.case.parse_case`, so the rules, units and one-line messages
are the command line's. The work a request may ask for is bounded here,
before any of it is done (:class:`Limits`): operating points, the nesting of
the fields, the body's size. Uploaded case files are parsed as TOML data
only. Nothing here opens a file.
"""

from __future__ import annotations

import json
import math
import warnings
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import tomlkit

from ..errors import BallScrewInputError, BallScrewPlausibilityWarning
from ..io.case import Case, parse_case, parse_toml
from ..io.units import range_size

__all__ = [
    "LIMITS",
    "ApiError",
    "Limits",
    "case_toml",
    "check_points",
    "load_case",
    "read_case_file",
    "read_json",
]


@dataclass(frozen=True)
class Limits:
    """What one request may ask for.

    Attributes
    ----------
    body_bytes : int
        Request body [bytes].
    points : int
        Operating points per model (speeds x temperatures x loads).
    models : int
        Models per request of the page.
    move_seconds : float
        Duration of the back-and-forth move whose energy is computed [s]
        (sampled every millisecond, as ``ballscrew energy`` does).
    depth : int
        Nesting of tables in the case fields (a case file needs 4).
    seconds : float
        Time a request may take, waiting included [s]: 503 past it, or after
        half of it waiting for the worker (one computation at a time).
    memory_bytes : int
        Address space a worker process may hold [bytes] (its interpreter and
        libraries take about 0.55 GiB of it): a request that needs more is
        answered 422, and no request can take the machine's memory.
    """

    body_bytes: int = 64 * 1024
    points: int = 2000
    models: int = 6
    move_seconds: float = 60.0
    depth: int = 6
    seconds: float = 10.0
    memory_bytes: int = 2 * 1024**3


LIMITS = Limits()


class ApiError(Exception):
    """A request refused: HTTP status and a one-line message (and the field, when one is at fault).

    A :class:`~ballscrew.errors.BallScrewInputError` becomes status 422 with its
    own message, the command line's.
    """

    def __init__(self, status: int, message: str, field: str = "") -> None:
        super().__init__(message)
        self.status = status
        self.message = message
        self.field = field

    @classmethod
    def from_input(cls, exc: BallScrewInputError) -> ApiError:
        """Status 422 with the message the command line prints after ``error:``."""
        return cls(422, str(exc), exc.field)

    def payload(self) -> dict[str, str]:
        """The JSON body of the refusal."""
        out = {"error": self.message}
        if self.field:
            out["field"] = self.field
        return out


class _TwiceError(Exception):
    """A key given twice in one JSON object (``json`` would keep the last without a word)."""

    def __init__(self, key: str) -> None:
        super().__init__(key)
        self.key = key


def _once(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    """A JSON object's pairs as a dict, refusing a key given twice."""
    out: dict[str, Any] = {}
    for key, value in pairs:
        if key in out:
            raise _TwiceError(key)
        out[key] = value
    return out


def read_json(body: bytes) -> dict[str, Any]:
    """A request body as a JSON object (400 if it is not one; 422 if it gives a key twice).

    A key given twice in one object (a move's ``stroke``, say) is refused, naming it, as
    the command line refuses a ``--move`` key given twice: JSON readers keep the last.
    """
    try:
        data = json.loads(body.decode("utf-8"), object_pairs_hook=_once)
    except _TwiceError as twice:
        raise ApiError.from_input(BallScrewInputError(
            twice.key, "(given twice)",
            "each key once in an object: which of the two is meant cannot be told",
        )) from None  # fmt: skip
    except (UnicodeDecodeError, ValueError, RecursionError):
        raise ApiError(400, "the request body is not JSON (UTF-8)") from None
    if not isinstance(data, dict):
        raise ApiError(400, "the request body must be a JSON object")
    try:  # JSON may escape a lone surrogate (\\ud800), which is no text at all
        json.dumps(data, ensure_ascii=False).encode("utf-8")
    except UnicodeEncodeError:
        raise ApiError(400, "the request body holds a lone surrogate: not text") from None
    return data


def _plain(value: Any, where: str, depth: int, limits: Limits) -> Any:
    """``value`` with JSON nulls left out, nesting bounded, assumed values as inline tables."""
    if depth > limits.depth:
        raise BallScrewInputError(where, "(nested tables)", f"at most {limits.depth} levels")
    if isinstance(value, Mapping):
        items = {str(k): _plain(v, f"{where}.{k}", depth + 1, limits) for k, v in value.items()}
        items = {k: v for k, v in items.items() if v is not None}
        if "assumed" in items:  # { value = "20 mm", assumed = "why" } stays on one line
            table = tomlkit.inline_table()
            table.update(items)
            return table
        return items
    if isinstance(value, list):
        return [_plain(v, f"{where}[{i}]", depth + 1, limits) for i, v in enumerate(value)]
    return value


def case_toml(fields: Mapping[str, Any], limits: Limits = LIMITS) -> str:
    """The case file (TOML text) with these fields; JSON nulls are keys left out.

    Examples
    --------
    >>> print(case_toml({"screw": {"designation": "40x10", "preload": "2 kN"},
    ...                  "lubricant": {"name": "PAO ISO VG 68", "nu40": None}}), end="")
    [screw]
    designation = "40x10"
    preload = "2 kN"
    <BLANKLINE>
    [lubricant]
    name = "PAO ISO VG 68"
    """
    plain = _plain(dict(fields), "case", 1, limits)
    try:
        return tomlkit.dumps(plain)
    except (TypeError, ValueError) as exc:  # e.g. a list mixing tables and values
        raise BallScrewInputError(
            "case", "(fields)", f"fields a TOML file can hold ({exc})"
        ) from None


def check_points(field: str, value: Any, limits: Limits) -> int:
    """How many values the text of a range asks for, refused above the limit before parsing."""
    if isinstance(value, Mapping):  # an assumed value
        value = value.get("value", "")
    count = range_size(str(value))
    if count > limits.points:
        raise BallScrewInputError(
            field, value, f"at most {limits.points} values per request (this asks for {count})"
        )
    return count


def load_case(fields: Mapping[str, Any], limits: Limits = LIMITS) -> Case:
    """The case the fields describe, read as the command line reads a case file."""
    operation = fields.get("operation")
    if isinstance(operation, Mapping):
        for key in ("speed", "temperature", "axial_load"):
            if operation.get(key) is not None:
                check_points(f"operation.{key}", operation[key], limits)
    with warnings.catch_warnings():  # the answer carries them (Case.warned), not the log
        warnings.simplefilter("ignore", BallScrewPlausibilityWarning)
        return parse_case(case_toml(fields, limits), source="case")


def read_case_file(body: bytes) -> dict[str, Any]:
    """``POST /api/case``: an uploaded case file's fields, read as TOML data (nothing else).

    The fields fill the page's form; they are checked when the page computes
    them, with the messages beside the fields. A file that is not UTF-8 TOML
    is refused with the command line's message.
    """
    try:
        text = body.decode("utf-8")
    except UnicodeDecodeError:
        raise ApiError.from_input(
            BallScrewInputError("case", "(file)", "a UTF-8 text file")
        ) from None
    try:
        fields = parse_toml(text, "case")
    except BallScrewInputError as exc:
        raise ApiError.from_input(exc) from None
    # Dates and times (TOML has them, case files do not) and inf or nan become
    # text, which the form shows and the computation then refuses by name.
    return {"fields": _as_text_where_json_cannot(fields)}


def _as_text_where_json_cannot(data: Any) -> Any:
    if isinstance(data, float) and not math.isfinite(data):
        return repr(data)
    if isinstance(data, dict):
        return {k: _as_text_where_json_cannot(v) for k, v in data.items()}
    if isinstance(data, list):
        return [_as_text_where_json_cannot(v) for v in data]
    if isinstance(data, str | int | float | bool):
        return data
    return str(data)
