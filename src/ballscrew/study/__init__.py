"""The study reproduction and the scorecard.

The study's series and figures (:mod:`.reproduce`), its findings in words
(:mod:`.findings`), the Sobol ranking of its uncertain inputs (:mod:`.sensitivity`),
and the validation cases and scoring (:mod:`.validation`).
"""
