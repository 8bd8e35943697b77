"""Fitting a model to a measurement, and friction for a controller.

Model parameters fitted to a measured curve with intervals (:mod:`.calibration`);
friction forms for servo controllers (:mod:`.controller`).
"""
