"""Choose the screw: catalogue candidates through the axis check, their Pareto front.

:func:`run_select` (``ballscrew select``) tries every catalogue nut the user's
filters leave, at each preload class and oil, on the user's axis and duty,
and returns a :class:`SelectResult`: every candidate's figures, the
non-dominated feasible ones over the objectives picked, and one recommended
by a stated rule (:mod:`.choose`).
"""

from .choose import (
    OBJECTIVES,
    Evaluated,
    NoFeasibleCandidateError,
    NoneFeasible,
    SelectResult,
    evaluate,
    non_dominated,
    run_select,
)
from .pool import PRELOAD_CLASSES, Candidate, candidates

__all__ = [
    "OBJECTIVES",
    "PRELOAD_CLASSES",
    "Candidate",
    "Evaluated",
    "NoFeasibleCandidateError",
    "NoneFeasible",
    "SelectResult",
    "candidates",
    "evaluate",
    "non_dominated",
    "run_select",
]
