"""The study reproduction and the scorecard.

The study's series and figures (:mod:`.reproduce`), its findings in words
(:mod:`.findings`), the Sobol ranking of its uncertain inputs (:mod:`.sensitivity`),
and the validation cases and scoring (:mod:`.validation`).

The commands' entry points: :func:`run_study` (``ballscrew study``) and
:func:`run_validate` (``ballscrew validate``).
"""

from .reproduce import StudyResult, run_study
from .validation import Scorecard, run_validate

__all__ = ["Scorecard", "StudyResult", "run_study", "run_validate"]
