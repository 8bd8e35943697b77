"""The candidates of a selection: screw x nut kind x preload class x oil (x motor).

The screws come from two sources (``sources``): the bundled catalogue rows
(``"catalogue"``), with their printed ratings, and the ISO 3408-2 size series
(``"iso"``, :data:`ISO_SIZES`), whose C_a and C_0a no catalogue gives: they
are estimated from the geometry by the methods the standard rests on
(:func:`~ballscrew.design.ratings.dynamic_rating_estimate`,
:func:`~ballscrew.design.ratings.static_rating_estimate`), and such a
candidate is labelled ``estimated``. :func:`rating_scatter` states how far
those estimates lie from the printed ratings of the catalogue rows.

Each candidate is the user's case with its ``[screw]`` (and, when an oil is
chosen, its ``[lubricant]``) replaced, kept as the case file's text, so that
any one of them can be written out and checked alone with ``ballscrew check``
and give the same numbers.

Preload classes are shares of the dynamic load rating C_a. The makers cap the
preload at 10 % of C_a (THK General Catalog, ball screw technical description,
"maximum preload"; HIWIN, Ballscrews & Accessories BS-08-2-EN-1704-K, 3.7.7),
and HIWIN keeps a single nut's within 5 % and a double nut's within 10 %
(same catalogue, 3.6.2 "Effects of preload" and 3.7.2, pp. 22 and 24). Within
that the package takes three classes: light 3 %, medium 5 % and heavy 8 %, so
that the heavy class is tried on double nuts only (:data:`SINGLE_NUT_LIMIT`).
The shares are this package's round choices inside the makers' ranges, not
one maker's table.

Nut kinds (:data:`NUT_KINDS`): ``double`` (two preloaded half-nuts),
``single-4point`` (one nut, oversize balls, 4-point contact), ``spacer-balls``
(a 4-point nut with a spacer ball between every two load balls: half the load
balls, less ball-to-ball sliding) and ``single`` (no preload, class "none").
A catalogue row is tried as the kind it is sold as (a single nut as 4-point;
spacer balls only for the ISO sizes, whose ratings are estimated from the
balls they hold); an ISO size as every kind.

ISO 3408-2 standardises the nominal diameters and leads of metric ball screws
and their preferred combinations. Its table was not at hand: the sizes here
are nominal diameters of 16 to 80 mm and leads of 5 to 40 mm in the
combinations the makers build, with the ball diameter and circuits of HIWIN's
catalogue where it has the size (BS-08-2-EN-1704-K, the rows bundled in
``data/catalog_screws.csv``) and, where it does not, those of the nearest
bundled size (each entry of ``ISO_SIZES`` names it).
"""

from __future__ import annotations

import functools
import math
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..design.ratings import RATING_CONFORMITY, dynamic_rating_estimate, static_rating_estimate
from ..errors import BallScrewInputError
from ..geometry import BallScrew
from ..io.designation import CatalogScrew, catalog_screws
from ..io.motors import MotorRow

__all__ = [
    "ISO_SIZES",
    "NUT_KINDS",
    "PRELOAD_CLASSES",
    "SOURCES",
    "Candidate",
    "candidates",
    "case_text",
    "iso_rows",
    "rating_scatter",
]

SOURCES: tuple[str, ...] = ("catalogue", "iso")
"""Where the screws come from: the bundled catalogue rows, the ISO 3408-2 size series."""

NUT_KINDS: tuple[str, ...] = ("double", "single-4point", "spacer-balls", "single")
"""The nut kinds a selection tries (module docstring)."""

ISO_SIZES: tuple[tuple[float, float, float, int, str], ...] = (
    # nominal diameter, lead, ball diameter [mm], circuits of one turn, where the ball is from
    (16, 5, 3.175, 3, "nearest bundled size (HIWIN 20x5)"),
    (16, 10, 3.175, 3, "nearest bundled size (HIWIN 14x10)"),
    (16, 16, 3.175, 2, "nearest bundled size (HIWIN 20x20)"),
    (20, 5, 3.175, 4, "HIWIN R20-05K4"),
    (20, 10, 3.969, 3, "nearest bundled size (HIWIN 25x10)"),
    (20, 20, 3.175, 2, "HIWIN R20-20K2"),
    (25, 5, 3.175, 4, "HIWIN R25-05K4"),
    (25, 10, 3.969, 4, "HIWIN R25-10K4"),
    (25, 20, 3.969, 3, "nearest bundled size of that diameter (HIWIN 25x10)"),
    (25, 25, 3.175, 2, "HIWIN R25-25K2"),
    (32, 5, 3.175, 4, "HIWIN R32-05K4"),
    (32, 10, 6.35, 5, "HIWIN R32-10K5"),
    (32, 20, 6.35, 4, "HIWIN R32-20K4"),
    (32, 32, 3.969, 2, "HIWIN R32-32K2"),
    (40, 5, 3.175, 5, "HIWIN R40-05K5"),
    (40, 10, 6.35, 5, "HIWIN R40-10K5"),
    (40, 20, 6.35, 4, "HIWIN R40-20K4"),
    (40, 40, 6.35, 2, "HIWIN R40-40K2"),
    (50, 5, 3.175, 5, "nearest bundled size (HIWIN 40x5)"),
    (50, 10, 6.35, 5, "HIWIN R50-10K5"),
    (50, 20, 9.525, 4, "HIWIN R50-20K4"),
    (63, 10, 6.35, 5, "HIWIN R63-10K5"),
    (63, 20, 9.525, 5, "HIWIN R63-20K5"),
    (80, 10, 6.35, 5, "nearest bundled size (HIWIN 63x10)"),
    (80, 20, 9.525, 5, "nearest bundled size (HIWIN 63x20)"),
)
"""The ISO 3408-2 sizes tried (mm; module docstring), each with its ball, its circuits (one
loaded turn each) and where the ball and circuits come from."""

SINGLE_NUT_LIMIT = 0.05
"""The largest preload share tried on a single nut (4-point, spacer balls): HIWIN keeps a
single nut's preload within 5 % of C_a, a double nut's within 10 % (BS-08-2-EN-1704-K, 3.6.2)."""

ESTIMATE_ANGLE = math.radians(45.0)
"""Contact angle of the estimates (the package's default; catalogues take 45 deg)."""

ESTIMATE_CONFORMITY = RATING_CONFORMITY
"""Groove conformity of the estimates: the makers' grooves, fitted on catalogue rows
(:data:`~ballscrew.design.ratings.RATING_CONFORMITY`); only the ratings take it."""

PRELOAD_CLASSES: dict[str, float] = {"none": 0.0, "light": 0.03, "medium": 0.05, "heavy": 0.08}
"""Preload classes as shares of C_a (module docstring; "none": a single nut with play)."""

DEFAULT_PRELOADS: tuple[str, ...] = ("light", "medium", "heavy")
"""The classes a selection tries unless told otherwise."""

_HEADER = re.compile(r"^\s*\[\[?\s*([A-Za-z0-9_.\"' -]+?)\s*\]\]?\s*(#.*)?$")
_CARRIED = ("contact_angle", "ball_separation")


@dataclass(frozen=True)
class Candidate:
    """One screw to try: a catalogue nut or ISO size, its nut kind, preload class, oil, motor.

    ``text`` is the whole case file of the candidate (TOML). ``estimated``:
    the screw's C_a and C_0a are estimates (an ISO size no catalogue row gives).
    ``price``: the motor's price (motor table) plus the screw's (``screw_price``,
    a screw price table), None when neither is given.
    """

    row: CatalogScrew
    nut: str
    preload_class: str
    preload_share: float
    oil: str
    text: str
    estimated: bool = False
    motor: MotorRow | None = None
    screw_price: float | None = None

    @property
    def name(self) -> str:
        """E.g. ``"HIWIN R32-10K5-FSC single-4point light, PAO ISO VG 68"``."""
        motor = f", {self.motor.name}" if self.motor is not None else ""
        return f"{self.row.name} {self.nut} {self.preload_class}, {self.oil}{motor}"

    @property
    def price(self) -> float | None:
        """The motor's and the screw's price, None when neither is given."""
        parts = [p for p in (self.motor.price if self.motor else None, self.screw_price)
                 if p is not None]  # fmt: skip
        return sum(parts) if parts else None


def _sections(text: str) -> list[tuple[str, list[str]]]:
    """The case file's lines grouped by table header ("" for the lines before the first)."""
    out: list[tuple[str, list[str]]] = [("", [])]
    for line in text.splitlines():
        match = _HEADER.match(line)
        if match and not line.lstrip().startswith("#"):
            out.append((match.group(1).strip().strip("\"'"), [line]))
        else:
            out[-1][1].append(line)
    return out


def _carried(lines: list[str]) -> list[str]:
    """The lines of the old ``[screw]`` that describe no catalogue value (contact angle)."""
    return [line for line in lines[1:] if line.split("=")[0].strip() in _CARRIED]


def _q(value: float, unit: str) -> str:
    """``value`` with ``unit`` as a case file's string, never a point before three digits.

    (The unit grammar refuses "314.159 rad/s": thousands or a decimal point?)
    """
    text = f"{value:.8g}"
    if re.fullmatch(r"[1-9]\d{0,2}\.\d{3}", text):
        text += "0"
    return f'"{text} {unit}"'


def _screw_lines(row: CatalogScrew, nut: str, estimated: bool) -> list[str]:
    """The ``[screw]`` lines naming ``row``: its designation, or its geometry and estimates."""
    if not estimated:
        return ["[screw]", f'designation = "{row.name}"', f'nut = "{nut}"']
    kind = "single-4point" if nut == "spacer-balls" else nut
    lines = [
        "[screw]",
        f"# {row.name}: ISO 3408-2 size, C_a and C_0a estimated (ballscrew.design.ratings)",
        f'pitch_diameter = "{row.nominal_diameter * 1e3:g} mm"',
        f'lead = "{row.lead * 1e3:g} mm"',
        f'ball_diameter = "{(row.ball_diameter or 0.0) * 1e3:g} mm"',
        f"loaded_turns = {row.loaded_turns or 1.0:g}",
        f"circuits = {row.circuits}",
        f'nut = "{kind}"',
    ]
    if nut == "spacer-balls":
        lines.append('ball_separation = "spacer-balls"')
    dynamic, static = _estimates(row, nut == "spacer-balls")
    lines.append(f"dynamic_load_rating = {_q(dynamic, 'N')}")
    lines.append(f"static_load_rating = {_q(static, 'N')}")
    return lines


def case_text(
    text: str, row: CatalogScrew, nut: str, share: float, oil: str | None,
    *, estimated: bool = False, motor: MotorRow | None = None,
) -> str:  # fmt: skip
    """``text`` (a case file) with its screw replaced by ``row`` as ``nut`` at ``share`` of C_a.

    With ``oil``, the ``[lubricant]`` table is replaced by that named lubricant;
    with ``motor``, the ``[motor]`` table and ``[axis]`` motor_inertia by the motor's.
    An ``estimated`` row is written as its geometry with its estimated ratings.
    """
    kept: list[str] = []
    carried: list[str] = []
    for name, lines in _sections(text):
        top = name.split(".")[0]
        if top == "screw":
            carried += _carried(lines) if name == "screw" else []
            continue
        if top == "lubricant" and oil is not None:
            continue
        if top == "motor" and motor is not None:
            continue
        if name == "axis" and motor is not None:
            lines = [ln for ln in lines if ln.split("=")[0].strip() != "motor_inertia"]
            lines.insert(1, f"motor_inertia = {_q(motor.rotor_inertia, 'kg*m^2')}")
        kept += lines
    screw = _screw_lines(row, nut, estimated)
    if nut != "single":
        screw.append(f'preload_share = "{share * 100:g} %"')
    else:
        screw.append('preload = "0 N"')
    screw += carried
    extra = ["", *screw]
    if oil is not None:
        extra += ["", "[lubricant]", f'name = "{oil}"']
    if motor is not None:
        extra += ["", "[motor]", f"# {motor.name} (motor table, line {motor.line})",
                  f"rated_torque = {_q(motor.rated_torque, 'N*m')}",
                  f"peak_torque = {_q(motor.peak_torque, 'N*m')}",
                  f"rated_speed = {_q(motor.max_speed, 'rad/s')}"]  # fmt: skip
        if motor.torque_constant is not None:
            extra.append(f"torque_constant = {_q(motor.torque_constant, 'N*m/A')}")
        if motor.winding_resistance is not None:
            extra += [f"winding_resistance = {_q(motor.winding_resistance, 'ohm')}",
                      f'resistance_kind = "{motor.resistance_kind}"']  # fmt: skip
        if motor.iron_loss is not None:
            extra.append(f'iron_loss = "{motor.iron_loss}"')
    return "\n".join(kept).rstrip("\n") + "\n" + "\n".join(extra) + "\n"


def _kinds(row: CatalogScrew, preload: str, estimated: bool) -> list[str]:
    """The nut kinds a row allows at a preload class (module docstring)."""
    if preload == "none":
        return ["single"] if estimated or row.nut != "double" else []
    single_ok = PRELOAD_CLASSES[preload] <= SINGLE_NUT_LIMIT
    if estimated:
        return ["double", *(["single-4point", "spacer-balls"] if single_ok else [])]
    if row.nut == "double":
        return ["double"]
    return ["single-4point"] if single_ok else []


def length_range(field: str, text: str | None) -> tuple[float, float] | None:
    """``"25..40 mm"`` (or one length) as (low, high) [m]; None when not given."""
    if text is None or not str(text).strip():
        return None
    from ..io.units import parse_range

    values = parse_range(field, str(text), "m", default_points=2)
    low, high = min(values), max(values)
    if not 0.0 < low <= high:
        raise BallScrewInputError(field, text, "lengths > 0, e.g. '25..40 mm'")
    return low, high


def _inside(value: float, bounds: tuple[float, float] | None) -> bool:
    return bounds is None or bounds[0] * (1 - 1e-9) <= value <= bounds[1] * (1 + 1e-9)


def rows(
    diameter: tuple[float, float] | None = None,
    lead: tuple[float, float] | None = None,
    makers: Sequence[str] = (),
) -> list[CatalogScrew]:
    """The catalogue rows inside the diameter and lead ranges [m] from the makers given."""
    wanted = {m.upper() for m in makers}
    return [
        r
        for r in catalog_screws()
        if _inside(r.nominal_diameter, diameter)
        and _inside(r.lead, lead)
        and (not wanted or r.maker.upper() in wanted)
        and r.dynamic_load_rating is not None
    ]


def _estimate_screw(row: CatalogScrew, spacer: bool) -> BallScrew:
    return BallScrew(
        row.pitch_diameter or row.nominal_diameter, row.lead, row.ball_diameter or 0.0,
        ESTIMATE_ANGLE, ESTIMATE_CONFORMITY, ESTIMATE_CONFORMITY, row.loaded_turns or 1.0,
        row.circuits, "single", ball_separation="spacer-balls" if spacer else "none",
    )  # fmt: skip


@functools.cache
def _estimates(row: CatalogScrew, spacer: bool = False) -> tuple[float, float]:
    """C_a and C_0a [N] the standard's methods give for ``row``'s geometry."""
    screw = _estimate_screw(row, spacer)
    return dynamic_rating_estimate(screw), static_rating_estimate(screw)


@functools.cache
def iso_rows() -> tuple[CatalogScrew, ...]:
    """The ISO 3408-2 sizes (:data:`ISO_SIZES`) as rows with estimated ratings."""
    out = []
    for d, lead, ball, circuits, where in ISO_SIZES:
        row = CatalogScrew(
            maker="ISO", designation=f"{d:g}x{lead:g}-{ball:g}", nut="single",
            nominal_diameter=d * 1e-3, pitch_diameter=None, lead=lead * 1e-3,
            ball_diameter=ball * 1e-3, circuits=circuits, loaded_turns=1.0,
            turns_status="assumed: one loaded turn per circuit", dynamic_load_rating=None,
            static_load_rating=None, source="ISO 3408-2 size; C_a and C_0a estimated",
            page="", notes=f"ball and circuits: {where}",
        )  # fmt: skip
        dynamic, static = _estimates(row)
        out.append(replace(row, dynamic_load_rating=dynamic, static_load_rating=static))
    return tuple(out)


def rating_scatter() -> dict[str, Any]:
    """The estimates against the printed ratings of the catalogue rows that print the geometry.

    For every bundled row with a ball diameter and loaded turns, the ratio
    estimated / printed of C_a and of C_0a: their median, 16 and 84 %
    percentiles, least and largest, and the number of rows.

    Examples
    --------
    >>> s = rating_scatter()
    >>> s["rows"], round(s["dynamic"]["median"], 3), round(s["static"]["median"], 2)
    (25, 0.962, 1.01)
    """
    ratios: dict[str, list[float]] = {"dynamic": [], "static": []}
    for row in catalog_screws():
        if None in (row.ball_diameter, row.loaded_turns, row.dynamic_load_rating,
                    row.static_load_rating):  # fmt: skip
            continue
        dynamic, static = _estimates(row)
        ratios["dynamic"].append(dynamic / float(row.dynamic_load_rating or 1.0))
        ratios["static"].append(static / float(row.static_load_rating or 1.0))
    out: dict[str, Any] = {"rows": len(ratios["dynamic"])}
    for key, values in ratios.items():
        v = np.array(values)
        p16, p50, p84 = np.percentile(v, [16, 50, 84])
        out[key] = {"median": float(p50), "p16": float(p16), "p84": float(p84),
                    "min": float(v.min()), "max": float(v.max())}  # fmt: skip
    return out


def scatter_text() -> str:
    """:func:`rating_scatter` in one line."""
    s = rating_scatter()
    d, c = s["dynamic"], s["static"]
    return (
        f"estimated/printed over {s['rows']} catalogue rows: C_a median {d['median']:.2f} "
        f"(16-84 %: {d['p16']:.2f}-{d['p84']:.2f}, range {d['min']:.2f}-{d['max']:.2f}), "
        f"C_0a median {c['median']:.2f} (16-84 %: {c['p16']:.2f}-{c['p84']:.2f}, "
        f"range {c['min']:.2f}-{c['max']:.2f})"
    )


def _screws(
    sources: Sequence[str], diameter: tuple[float, float] | None,
    lead: tuple[float, float] | None, makers: Sequence[str],
) -> list[tuple[CatalogScrew, bool]]:  # fmt: skip
    """The screws of the sources inside the filters, each with whether it is estimated.

    An ISO size a kept catalogue row already gives (same diameter and lead) is left out:
    its printed ratings are better than an estimate.
    """
    out: list[tuple[CatalogScrew, bool]] = []
    if "catalogue" in sources:
        out += [(r, False) for r in rows(diameter, lead, makers)]
    if "iso" in sources and (not makers or "ISO" in {m.upper() for m in makers}):
        printed = {(round(r.nominal_diameter, 6), round(r.lead, 6)) for r, _ in out}
        out += [
            (r, True) for r in iso_rows()
            if _inside(r.nominal_diameter, diameter) and _inside(r.lead, lead)
            and (round(r.nominal_diameter, 6), round(r.lead, 6)) not in printed
        ]  # fmt: skip
    return out


MAX_CANDIDATES = 10_000
"""The most candidates one selection evaluates (each runs the whole axis check and a cycle
energy); more are refused before any is built, with the estimate."""
RATE = 50.0
"""Candidates evaluated per CPU-second on one core, the estimate of a refused selection's time:
``benchmarks/bench_select.py --grid`` (no motor table) on a loaded machine; a motor table's
candidates, which share their heat balance and friction, go about twice as fast."""


def candidates(
    text: str,
    *,
    diameter: tuple[float, float] | None = None,
    lead: tuple[float, float] | None = None,
    makers: Sequence[str] = (),
    preloads: Sequence[str] = DEFAULT_PRELOADS,
    oils: Sequence[str | None] = (None,),
    default_oil: str = "",
    sources: Sequence[str] = ("catalogue",),
    nuts: Sequence[str] = (),
    motors: Sequence[MotorRow] = (),
    screw_prices: Mapping[str, float] | None = None,
) -> list[Candidate]:
    """Every candidate of the filters on the case file ``text`` (module docstring).

    ``sources``: :data:`SOURCES` to draw the screws from; ``nuts``: the
    :data:`NUT_KINDS` to keep (all when empty); ``motors``: a motor table's
    rows, each screw tried with each (the case's motor when empty);
    ``screw_prices``: a screw price table (screw name -> price), whose every
    screw tried must be in it.

    Raises :class:`~ballscrew.errors.BallScrewInputError` for an unknown
    source, nut kind, preload class or maker, and when no screw passes the
    filters (naming the closest).
    """
    for p in preloads:
        if p not in PRELOAD_CLASSES:
            raise BallScrewInputError("--preload", p, f"one of {', '.join(PRELOAD_CLASSES)}")
    for src in sources:
        if src not in SOURCES:
            raise BallScrewInputError("--source", src, f"one of {', '.join(SOURCES)}")
    for n in nuts:
        if n not in NUT_KINDS:
            raise BallScrewInputError("--nut", n, f"one of {', '.join(NUT_KINDS)}")
    known = sorted({r.maker for r in catalog_screws()} | ({"ISO"} if "iso" in sources else set()))
    for m in makers:
        if m.upper() not in {k.upper() for k in known}:
            raise BallScrewInputError("--maker", m, f"one of {', '.join(known)}")
    found = _screws(sources, diameter, lead, makers)
    if not found:
        raise BallScrewInputError(
            "--diameter/--lead/--maker",
            _shown(diameter, lead, makers),
            "filters some screw passes; closest: " + _closest(diameter, lead, sources),
        )
    prices = {" ".join(k.split()).upper(): v for k, v in (screw_prices or {}).items()}
    if screw_prices is not None:
        missing = sorted({r.name for r, _ in found if r.name.upper() not in prices})
        if missing:
            raise BallScrewInputError(
                "--screw-prices", f"{len(missing)} screws without a price",
                "a price for every screw the filters leave; missing: " + ", ".join(missing[:5])
                + (", ..." if len(missing) > 5 else ""),
            )  # fmt: skip
    paired_count = max(1, len(motors))
    count = sum(len(oils) * paired_count for row, estimated in found for p in preloads
                for nut in _kinds(row, p, estimated) if not nuts or nut in nuts)  # fmt: skip
    if count > MAX_CANDIDATES:
        raise BallScrewInputError(
            "candidates", f"{count} ({len(found)} screws x preload classes and nut kinds x "
            f"{len(oils)} oils x {paired_count} motors)",
            f"at most {MAX_CANDIDATES} a selection (about {count / RATE / 60:.0f} min of CPU at "
            f"{RATE:g} candidates a second): narrow --diameter, --lead, --maker, --preload, "
            "--nut, the oils or the motor table",
        )  # fmt: skip
    out = []
    for row, estimated in found:
        for p in preloads:
            for nut in _kinds(row, p, estimated):
                if nuts and nut not in nuts:
                    continue
                for oil in oils:
                    paired: list[MotorRow | None] = list(motors) or [None]
                    for motor in paired:
                        new = case_text(text, row, nut, PRELOAD_CLASSES[p], oil,
                                        estimated=estimated, motor=motor)  # fmt: skip
                        out.append(Candidate(row, nut, p, PRELOAD_CLASSES[p], oil or default_oil,
                                             new, estimated, motor,
                                             prices.get(row.name.upper())))  # fmt: skip
    if not out:
        raise BallScrewInputError(
            "--preload/--nut", ", ".join([*preloads, *nuts]),
            "a class and nut kind the screws allow ('none' needs a single nut, 'heavy' a double "
            "nut: HIWIN keeps single nuts within 5 % of C_a; catalogue rows come as sold, "
            "spacer balls only for ISO sizes): "
            + ", ".join(f"{r.name} ({r.nut})" for r, _ in found[:3]),
        )  # fmt: skip
    return out


def _shown(
    diameter: tuple[float, float] | None, lead: tuple[float, float] | None, makers: Sequence[str]
) -> str:
    parts = []
    for name, b in (("diameter", diameter), ("lead", lead)):
        if b is not None:
            parts.append(f"{name} {b[0] * 1e3:g}..{b[1] * 1e3:g} mm")
    if makers:
        parts.append("maker " + ", ".join(makers))
    return "; ".join(parts) or "(none)"


def _gap(value: float, bounds: tuple[float, float] | None) -> float:
    if bounds is None:
        return 0.0
    low, high = bounds
    return max(low - value, value - high, 0.0) / max(high, 1e-9)


def _closest(
    diameter: tuple[float, float] | None, lead: tuple[float, float] | None,
    sources: Sequence[str] = ("catalogue",),
) -> str:  # fmt: skip
    pool = list(catalog_screws()) + (list(iso_rows()) if "iso" in sources else [])
    ranked = sorted(pool, key=lambda r: _gap(r.nominal_diameter, diameter) + _gap(r.lead, lead))
    return ", ".join(
        f"{r.name} ({r.nominal_diameter * 1e3:g} x {r.lead * 1e3:g} mm)" for r in ranked[:3]
    )
