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

    def as_dict(self) -> dict[str, Any]:
        """The curve and what it was computed with (speeds [rpm], torques [N·m])."""
        return {
            "label": self.label, "model": self.model,
            "speed_rpm": [float(v) for v in self.speed_rpm],
            "torque_Nm": [float(v) for v in self.torque],
            "preload_N": self.preload, "temperature_C": self.temperature,
            "lubricant": self.lubricant, "parameters": dict(self.parameters),
        }  # fmt: skip


@dataclass(frozen=True)
class Figure:
    """A figure of the study (or one it lacks) with its series."""

    key: str
    title: str
    caption: str
    series: tuple[Series, ...]
    log_y: bool = False
    stacked: bool = False

    def as_dict(self) -> dict[str, Any]:
        """The figure's key, title, caption and series."""
        return {"key": self.key, "title": self.title, "caption": self.caption,
                "series": [s.as_dict() for s in self.series]}  # fmt: skip
