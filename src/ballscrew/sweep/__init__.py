"""Sweeps over design spaces and uncertain inputs.

The sweep file and its axes (:mod:`.spec`), the fields a sweep may vary
(:mod:`.fields`), the uncertain inputs (:mod:`.uncertainty`), the grid and its chunks
(:mod:`.plan`), running them in process or on Dask (:mod:`.execute`), the Zarr store
(:mod:`.store`), Monte Carlo and Sobol sampling and indices (:mod:`.sensitivity`).
"""
