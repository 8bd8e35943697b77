"""Sweeps over design spaces and uncertain inputs.

A pipeline: the sweep file and its axes (:mod:`.spec`, with the fields a sweep may vary,
:mod:`.fields`, and the uncertain inputs, :mod:`.uncertainty`) -> the grid, its chunks
and the store's layout (:mod:`.plan`) -> each chunk computed (:mod:`.compute`) -> the
Zarr store, which writes what it is handed (:mod:`.store`). :func:`run_sweep`
(:mod:`.execute`) runs it in process or on Dask; :mod:`.sensitivity` samples the
uncertain inputs and estimates the Sobol indices.
"""

from .execute import SweepReport, run_sweep

__all__ = ["SweepReport", "run_sweep"]
