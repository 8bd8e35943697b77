"""Documents and files.

Figures (:mod:`.plotting`), Markdown and HTML (:mod:`.document`), result tables with
their provenance (:mod:`.outputs`), and one module per report: the study
(:mod:`.study`), axis energy (:mod:`.energy`), a fit (:mod:`.fit`), the scorecard
(:mod:`.validation`).
"""
