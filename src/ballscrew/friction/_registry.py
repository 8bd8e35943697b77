"""Registry of friction models: name, function, reference and validity range."""

from __future__ import annotations

import inspect
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Protocol, TypeVar

import numpy as np

from ..errors import BallScrewInputError, FloatArray
from ..geometry import BallScrew, ScrewGeometry
from ..lubricant import Lubricant
from ..numerics.single import broadcast_shape, broadcast_to
from ..validity import ValidityCheck

__all__ = [
    "MODELS",
    "NONE_MEANS",
    "PARAMETER_RANGES",
    "PARAMETER_UNITS",
    "FrictionModel",
    "ModelFunction",
    "ModelSpec",
    "get_model",
    "register",
]


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
    batches : callable, optional
        Given the parameters as used, whether the model takes many screws at once as a
        :class:`ballscrew.geometry.ScrewArray` (every layer with the geometry as
        broadcast arrays, first axis the screws); None: one screw at a time.
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
    batches: Callable[[dict[str, Any]], bool] | None = None

    def check_names(self, given: dict[str, Any]) -> None:
        """Raise if ``given`` holds a parameter the model does not have."""
        for key in given:
            if key not in self.parameters:
                allowed = sorted(self.parameters) or ["(none)"]
                raise BallScrewInputError(
                    key, given[key], f"a parameter of model {self.name!r}: {allowed}"
                )

    def check_parameters(self, given: dict[str, Any]) -> None:
        """Raise if ``given`` holds a parameter the model lacks, or a value of the wrong kind.

        A value must be of its default's kind (a truth value, a name, a number; a
        number where the default is None) and, for the parameters of
        :data:`PARAMETER_RANGES`, inside their physical range.
        """
        self.check_names(given)
        for key, value in given.items():
            _check_value(key, value, self.parameters[key])

    def __call__(
        self, screw: ScrewGeometry, lubricant: Lubricant, speed: FloatArray,
        temperature: FloatArray, axial_load: FloatArray, state: Any = None, **params: Any,
    ) -> dict[str, FloatArray]:  # fmt: skip
        """Evaluate the model (parameters checked first), with the contact state if given."""
        self.check_parameters(params)
        if state is not None and self.uses_state:
            params = {**params, "state": state}
        # Many screws (a ScrewArray) reach only the models that take them (``batches``).
        function: Any = self.function
        out = function(screw, lubricant, speed, temperature, axial_load, **params)
        # Many screws (a ScrewArray): their geometry's axes count among the points'.
        shape = broadcast_shape(
            speed.shape, temperature.shape, axial_load.shape, np.shape(screw.lead)
        )
        return {k: broadcast_to(np.asarray(v, dtype=float), shape) for k, v in out.items()}


PARAMETER_RANGES: dict[str, tuple[float, float, str]] = {
    # Coulomb and traction coefficients of lubricated steel: 0.001 to about 0.15 measured;
    # above 1 no lubricated steel contact goes (dry hardened steel is 0.6 to 0.8).
    "mu0": (0.0, 1.0, "a friction coefficient"),
    "boundary_friction": (0.0, 1.0, "a friction coefficient"),
    "ball_ball_friction": (0.0, 1.0, "a friction coefficient"),
    "friction_coefficient": (0.0, 1.0, "a friction coefficient"),
    "sliding_coefficient": (0.0, 1.0, "a friction coefficient"),
    "limiting_shear_coefficient": (0.0, 1.0, "a limiting shear over pressure"),
    "kappa": (0.0, 1.0, "a ratio of 0 to 1"),
    # The makers' preload drag coefficient K is 0.05 (THK) with 0.01 to 0.1 in use.
    "preload_coefficient": (0.0, 1.0, "a drag coefficient of 0 to 1"),
    "ball_train_constant": (0.0, 1.0, "a force ratio of 0 to 1"),
    "hysteresis_loss_factor": (0.0, 1.0, "a loss factor of 0 to 1 (steel: about 0.01)"),
    # Shear stresses: the limiting shear stress of oils is 1 to 100 MPa; 10 GPa is the
    # shear strength of steel's order, past which no lubricant film goes.
    "limiting_shear_stress": (0.0, 1e10, "a stress of 0 to 10 GPa"),
    "eyring_stress": (0.0, 1e10, "a stress of 0 to 10 GPa"),
    "return_turning_angle": (0.0, 8.0 * np.pi, "an angle of 0 to 4 turns [rad]"),
    "seal_torque": (0.0, 1000.0, "a torque of 0 to 1000 N*m"),
    "ball_ball_force": (0.0, 1e6, "a force of 0 to 1 MN"),
    "asperity_b": (0.0, 100.0, "a fit constant of 0 to 100"),
    "asperity_c": (0.0, 100.0, "a fit constant of 0 to 100"),
    "rheology_exponent": (0.0, 100.0, "an exponent of 0 to 100"),
}
"""Physical range of each numeric model parameter that has one: (low, high, in words).

A value outside is refused by :meth:`ModelSpec.check_parameters`: a parameter of 1e10 or
more gave torques up to 2e301 N·m in 0.2.0. Other numeric parameters (the viscoelastic
bed's constants per unit area) must be finite and non-negative."""


PARAMETER_UNITS: dict[str, tuple[str, str]] = {
    # name: (unit, meaning). Unit "-" is a pure number; "" a name or a truth value.
    "preload_coefficient": ("-", "c in the catalogue's preload drag K = c / sqrt(tan(lead angle))"),
    "friction_coefficient": ("-", "friction coefficient of the catalogue efficiency"),
    "boundary_friction": ("-", "friction coefficient of asperity contact (ball-groove, "
                          "ball-ball, return path)"),
    "limiting_shear_stress": ("Pa", "limiting shear stress tau_0 of the full-film traction"),
    "limiting_shear_coefficient": ("-", "limiting shear stress over pressure, gamma_L"),
    "ball_train": ("", "how the ball-train force is found: 'ratio' (F_B = c_B Q) or "
                   "'tolerance' (from scattered contact angles)"),
    "ball_train_constant": ("-", "c_B = F_B / Q, ball-train force over ball load ('ratio')"),
    "contact_angle_scatter": ("rad", "standard deviation of the balls' contact angles "
                              "('tolerance')"),
    "return_turning_angle": ("rad", "angle the balls turn through in the return path"),
    "hysteresis_loss_factor": ("-", "share of the rolling strain energy lost (steel: ~0.01)"),
    "lubrication": ("", "lubrication method: 'flooded' or 'circulating' (a nut full of oil: "
                    "oil shear between balls, ball churning, no starvation), 'drip', "
                    "'oil-air' or 'grease'; 'auto': 'grease' for a grease, else 'drip'"),
    "thermal_correction": ("", "apply the inlet shear heating and replenishment factors"),
    "seal_torque": ("N*m", "drag torque of wipers or seals"),
    "asperity_b": ("-", "B of the asperity share A_c/A_0 against the film parameter"),
    "asperity_c": ("-", "C of the asperity share A_c/A_0 against the film parameter"),
    "hertz_method": ("", "Hertz solution: 'exact', 'houpert', ..."),
    "mu0": ("-", "boundary friction coefficient mu_0"),
    "sliding_coefficient": ("-", "c_v, the share of the contact slipping against rolling"),
    "sliding_sign_on_lubricant": ("", "apply c_v to the lubricant's shear too"),
    "shear_velocity": ("", "speed of the film's shear: 'rolling' or 'sliding'"),
    "rheology_model": ("", "shear law: 'harmonic', 'general', 'eyring' or 'bair-winer'"),
    "rheology_exponent": ("-", "exponent n of the 'general' shear law"),
    "eyring_stress": ("Pa", "Eyring stress tau_E of the 'eyring' shear law"),
    "pressure_viscosity_model": ("", "viscosity against pressure: 'roelands' or 'barus'"),
    "torque_arm": ("", "lever arm of the contact forces: 'energy', 'contact-radius' or "
                   "'ball-radius'"),
    "nodes": ("-", "quadrature nodes"),
    "film": ("", "film thickness of the shear rate: 'central' or 'minimum'"),
    "sliding_friction": ("", "how the sliding friction coefficient is found: 'asperity' or "
                         "'speed-fit'"),
    "kappa": ("-", "kappa of the radius R_a = (D_w/2)(1 + kappa)/(1 + kappa/2) of the "
              "sliding moment (0.02 to 0.1)"),
    "ball_ball_force": ("N", "force between neighbouring balls F_B"),
    "ball_ball_friction": ("-", "friction coefficient between balls mu_b"),
    "include_pivoting": ("", "add the spin power of the pivoting moment"),
    "hysteresis_units": ("", "units the elastic hysteresis moment's coefficient is read in: "
                         "'SI' or 'N·mm'"),
    "stiffness": ("N/m^3", "stiffness of the viscoelastic bed per unit area"),
    "mass": ("kg/m^2", "mass of the viscoelastic bed per unit area"),
    "damping": ("N*s/m^3", "damping of the viscoelastic bed per unit area"),
    "leading_edge": ("", "include the leading edge's force and power"),
    "edge_power": ("", "the leading edge's power: 'kinetic' or 'work'"),
}  # fmt: skip
"""Each model parameter's unit and meaning, as ``ballscrew models`` lists them."""

NONE_MEANS: dict[str, str] = {
    "limiting_shear_stress": "the lubricant's",
    "limiting_shear_coefficient": "the lubricant's",
    "eyring_stress": "none: needed only with rheology_model 'eyring'",
}
"""What a parameter's default None stands for."""


def _check_value(key: str, value: Any, default: Any) -> None:
    """``value`` of the kind of ``default`` and inside :data:`PARAMETER_RANGES`."""
    if isinstance(default, bool):
        if not isinstance(value, bool | np.bool_):
            raise BallScrewInputError(key, value, "true or false")
        return
    if isinstance(default, str):
        if not isinstance(value, str):
            raise BallScrewInputError(key, value, f"a name, such as {default!r}")
        return
    if isinstance(default, tuple):
        if not (isinstance(value, list | tuple) and len(value) == len(default)):
            raise BallScrewInputError(key, value, f"{len(default)} whole numbers, like {default}")
        for v in value:
            _check_value(key, v, default[0])
        return
    if value is None and default is None:
        return
    if isinstance(value, bool | np.bool_) or not isinstance(value, int | float | np.number):
        raise BallScrewInputError(key, value, "a real number")
    number = float(value)
    low, high, words = PARAMETER_RANGES.get(key, (0.0, np.inf, "a finite number, 0 or more"))
    if not (low <= number <= high) or not np.isfinite(number):
        raise BallScrewInputError(key, value, words)
    if isinstance(default, int) and not isinstance(default, bool) and number != int(number):
        raise BallScrewInputError(key, value, "a whole number")


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
    batches: Callable[[dict[str, Any]], bool] | None = None,
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
            uses_state="state" in sig.parameters, batches=batches,
        )  # fmt: skip
        return func

    return deco


def get_model(name: str) -> ModelSpec:
    """The registered model ``name``; an unknown name lists the valid ones."""
    try:
        return MODELS[name]
    except (KeyError, TypeError):
        raise BallScrewInputError("model", name, f"one of {sorted(MODELS)}") from None
