"""Registry of friction models: name, function, reference and validity range."""

from __future__ import annotations

import inspect
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Protocol, TypeVar

import numpy as np

from ..errors import BallScrewInputError, FloatArray
from ..geometry import BallScrew
from ..lubricant import Lubricant
from ..validity import ValidityCheck

__all__ = ["MODELS", "FrictionModel", "ModelFunction", "ModelSpec", "get_model", "register"]


class FrictionModel(Protocol):
    """A friction model, the one signature every model has.

    Called as ``f(screw, lubricant, speed, temperature, axial_load, **params)``:
    ``speed`` [rad/s], ``temperature`` [°C] and ``axial_load`` [N] arrive as
    broadcast float arrays of one shape; ``params`` are the model's own keyword-only
    parameters with their defaults (and ``state``, the contact state, for a model that
    asks for it). The model returns a mapping of named torque contributions on the
    screw [N·m], each of that shape, non-negative, whose sum is the friction torque.
    """

    def __call__(
        self, screw: BallScrew, lubricant: Lubricant, speed: FloatArray, temperature: FloatArray,
        axial_load: FloatArray, /, *args: Any, **params: Any,
    ) -> dict[str, FloatArray]:  # fmt: skip
        """The model's named torque contributions [N·m] at the broadcast points."""


ModelFunction = FrictionModel
"""The former name of :class:`FrictionModel`."""

M = TypeVar("M", bound=FrictionModel)


@dataclass(frozen=True)
class ModelSpec:
    """A registered friction model.

    Attributes
    ----------
    name : str
        Registry name, e.g. ``"harris-simplified"``.
    function : FrictionModel
        The model.
    title : str
        One-line description.
    reference : str
        Main reference (with DOI where one exists).
    validity : str
        Published or stated validity range, in words.
    parameters : dict
        The model's own keyword parameters and their defaults.
    purpose : str
        What the model is for (to predict, to reproduce the study, ...).
    checks : tuple of ValidityCheck
        The validity checks that apply to the model (see
        :mod:`ballscrew.validity`): the model declares them beside its
        equations, including checks of its own ranges.
    chunk : int
        Operating points the chain evaluates at once (bounds memory).
    uses_state : bool
        The model takes the contact state (a keyword argument ``state``): the
        chain builds it once, with the model's ``hertz_method``,
        ``asperity_b`` and ``asperity_c``, passes it in and keeps it on the
        result.
    """

    name: str
    function: FrictionModel
    title: str
    reference: str
    validity: str
    parameters: dict[str, Any] = field(default_factory=dict)
    purpose: str = ""
    chunk: int = 1 << 17
    checks: tuple[ValidityCheck, ...] = ()
    uses_state: bool = False

    def check_parameters(self, given: dict[str, Any]) -> None:
        """Raise if ``given`` holds a parameter the model does not have."""
        for key in given:
            if key not in self.parameters:
                allowed = sorted(self.parameters) or ["(none)"]
                raise BallScrewInputError(
                    key, given[key], f"a parameter of model {self.name!r}: {allowed}"
                )

    def __call__(
        self, screw: BallScrew, lubricant: Lubricant, speed: FloatArray, temperature: FloatArray,
        axial_load: FloatArray, state: Any = None, **params: Any,
    ) -> dict[str, FloatArray]:  # fmt: skip
        """Evaluate the model (parameters checked first), with the contact state if given."""
        self.check_parameters(params)
        if state is not None and self.uses_state:
            params = {**params, "state": state}
        out = self.function(screw, lubricant, speed, temperature, axial_load, **params)
        shape = np.broadcast_shapes(speed.shape, temperature.shape, axial_load.shape)
        return {k: np.broadcast_to(np.asarray(v, dtype=float), shape) for k, v in out.items()}


MODELS: dict[str, ModelSpec] = {}
"""All registered friction models, by name."""


def register(
    name: str,
    *,
    title: str,
    reference: str,
    validity: str,
    purpose: str = "",
    chunk: int = 1 << 17,
    checks: tuple[ValidityCheck, ...] = (),
) -> Callable[[M], M]:
    """Register a model function under ``name`` (decorator).

    The model's parameters and defaults are read from its keyword-only
    arguments (a keyword ``state`` is not a parameter: it asks the chain for
    the contact state, see :class:`ModelSpec`); ``chunk`` is the number of
    operating points evaluated at once (chosen so that the model's largest
    temporary arrays stay near 100 MB).
    """

    def deco(func: M) -> M:
        sig = inspect.signature(func)
        params = {
            p.name: p.default
            for p in sig.parameters.values()
            if p.kind is inspect.Parameter.KEYWORD_ONLY and p.name != "state"
        }
        MODELS[name] = ModelSpec(
            name, func, title, reference, validity, params, purpose, chunk, checks,
            uses_state="state" in sig.parameters,
        )  # fmt: skip
        return func

    return deco


def get_model(name: str) -> ModelSpec:
    """The registered model ``name``; an unknown name lists the valid ones."""
    try:
        return MODELS[name]
    except (KeyError, TypeError):
        raise BallScrewInputError("model", name, f"one of {sorted(MODELS)}") from None
