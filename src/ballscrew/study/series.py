"""The study's plotted data: a series (torque against speed) and a figure of series."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from ..errors import FloatArray

__all__ = ["Figure", "Series"]


@dataclass(frozen=True)
class Series:
    """One plotted curve: friction torque against screw speed."""

    label: str
    model: str
    speed_rpm: FloatArray
    torque: FloatArray
    preload: float
    temperature: float
    lubricant: str
    parameters: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class Figure:
    """A figure of the study (or one it lacks) with its series."""

    key: str
    title: str
    caption: str
    series: tuple[Series, ...]
    log_y: bool = False
    stacked: bool = False
