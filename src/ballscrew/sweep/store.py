"""The Zarr store of a sweep: written as it is handed, resume markers, statistics, the rename.

The store is Zarr format 2 with consolidated metadata, read back with
``xarray.open_zarr(path)``. Its attributes carry the sweep file's text, the
case file's text, the resolved screw and lubricant, every model's parameters
(defaults filled in), the unit of every variable and the package version.

The store is handed what it writes: the layout (:class:`Layout`, from
:func:`ballscrew.sweep.plan.layout`),
each chunk's blocks and report (:func:`ballscrew.sweep.compute.compute_chunk`), the
computed variables and the closing attributes. It never reads the plan.
"""

from __future__ import annotations

import contextlib
import glob
import json
import secrets
import shutil
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

import numpy as np

from ..errors import BallScrewInputError, FloatArray
from ..io.files import atomic_write, deferred_signals, swap_in

__all__ = [
    "FORMAT",
    "Layout",
    "add_variables",
    "check_target",
    "create",
    "finalize",
    "json_safe",
    "markers",
    "mean_torque",
    "partial_path",
    "percentile_variables",
    "sobol_variables",
    "write_chunk",
]  # fmt: skip

FORMAT: Literal[2] = 2
"""Zarr format: 2 stores text coordinates (model and component names) in a
stable, specified way, and consolidated metadata; both are still unstable
extensions in format 3."""

FINGERPRINT = "fingerprint"


@dataclass(frozen=True)
class Layout:
    """What a sweep's store holds before any chunk is computed (plain data).

    Attributes
    ----------
    coords : dict
        Coordinate name -> (dimensions, values, attributes), in the store's order.
    variables : dict
        Output name -> (dimensions, shape, chunks, attributes): arrays of NaN to fill.
    attrs : dict
        The store's attributes (JSON-safe).
    """

    coords: dict[str, tuple[tuple[str, ...], Any, dict[str, Any]]]
    variables: dict[str, tuple[tuple[str, ...], tuple[int, ...], tuple[int, ...], dict[str, Any]]]
    attrs: dict[str, Any]


def json_safe(value: Any) -> Any:
    """A copy of nested mappings and sequences that JSON (and Zarr's attributes) take."""
    if isinstance(value, dict):
        return {str(k): json_safe(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [json_safe(v) for v in value]
    if isinstance(value, np.generic):
        return value.item()
    if value is None or isinstance(value, str | int | float | bool):
        return value
    return str(value)


def partial_path(out: Path) -> Path:
    """Folder of an unfinished run.

    It holds ``store.zarr`` (renamed to ``out`` when complete) and
    ``progress/`` (the sweep's fingerprint and one marker per finished chunk).
    """
    return out.parent / f".{out.name}.partial"


def store_path(partial: Path) -> Path:
    """The store inside a partial folder."""
    return partial / "store.zarr"


def progress_path(partial: Path) -> Path:
    """The chunk markers inside a partial folder."""
    return partial / "progress"


def _dataset(layout: Layout) -> Any:
    """The layout as an xarray Dataset of lazy NaN arrays (nothing is computed)."""
    import dask.array as da
    import xarray as xr

    coords = {name: xr.Variable(*c) for name, c in layout.coords.items()}
    data = {
        name: xr.Variable(dims, da.full(shape, np.nan, chunks=chunks), attrs)
        for name, (dims, shape, chunks, attrs) in layout.variables.items()
    }
    return xr.Dataset(data, coords=coords, attrs=layout.attrs)


def create(layout: Layout, partial: Path, fingerprint: str) -> None:
    """Write the layout (coordinates, attributes, empty arrays) and the fingerprint."""
    if partial.exists():
        shutil.rmtree(partial)
    dataset = _dataset(layout)
    encoding = {name: {"chunks": dataset[name].data.chunksize} for name in layout.variables}
    dataset.to_zarr(store_path(partial), mode="w", compute=False, consolidated=False,
                    zarr_format=FORMAT, encoding=encoding)  # fmt: skip
    progress_path(partial).mkdir()
    (progress_path(partial) / FINGERPRINT).write_text(fingerprint, encoding="utf-8")


_ARRAYS: dict[tuple[str, str], dict[str, Any]] = {}
"""Open Zarr arrays per (store, fingerprint), reused by the chunks a process writes."""


def _arrays(store: str, key: str, names: Sequence[str]) -> dict[str, Any]:
    import zarr

    if (store, key) not in _ARRAYS or not set(names) <= _ARRAYS[(store, key)].keys():
        group = zarr.open_group(store, mode="r+", zarr_format=FORMAT)
        _ARRAYS.clear()
        _ARRAYS[(store, key)] = {name: group[name] for name in names}
    return _ARRAYS[(store, key)]


def write_chunk(
    partial: Path,
    fingerprint: str,
    blocks: Mapping[str, tuple[tuple[slice, ...], FloatArray]],
    report: Mapping[str, Any],
) -> None:
    """Write a chunk's blocks (each into its region), then mark the chunk done with its report."""
    arrays = _arrays(str(store_path(partial)), fingerprint, list(blocks))
    with deferred_signals():  # a chunk is written whole before Ctrl-C is acted on
        for name, (region, values) in blocks.items():
            arrays[name][region] = values
        marker = progress_path(partial) / f"{report['index']}.json"
        atomic_write(marker, json.dumps(report).encode("utf-8"))


def markers(partial: Path, fingerprint: str) -> dict[int, dict[str, Any]] | None:
    """The reports of the chunks marked done in a partial run; None if it is another sweep's."""
    try:
        found = (progress_path(partial) / FINGERPRINT).read_text(encoding="utf-8")
    except OSError:
        return None
    if found != fingerprint:
        return None
    done: dict[int, dict[str, Any]] = {}
    for marker in progress_path(partial).glob("*.json"):
        try:
            report = json.loads(marker.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            continue  # a marker is written atomically; anything else is not one
        done[int(report["index"])] = report
    return done


def add_variables(partial: Path, variables: dict[str, Any]) -> None:
    """Add computed variables (percentiles, Sobol indices) to a partial store."""
    import xarray as xr
    import zarr

    path = store_path(partial)
    attrs = dict(zarr.open_group(path, mode="r", zarr_format=FORMAT).attrs)
    # Appending rewrites the group's attributes: keep them.
    xr.Dataset(variables, attrs=attrs).to_zarr(
        path, mode="a", consolidated=False, zarr_format=FORMAT
    )


def figure_path(out: Path, model: str, kind: str) -> Path:
    """Where the sensitivity figure of ``model`` drawn from the store ``out`` is written."""
    return out.parent / f"{out.name}.sensitivity-{model}.{kind}"


def finalize(
    partial: Path, out: Path, extra_attrs: dict[str, Any], companions: Sequence[Path] = ()
) -> None:
    """Consolidate the metadata, rename the store to ``out`` and drop the partial folder.

    The figures an earlier run drew from the store it replaces (:func:`figure_path`) are
    moved aside with it, and so are the ``companions`` (files written from it, such as a
    summary JSON), so that a run stopped before it writes its own leaves the new store
    alone, never beside an earlier run's figures or summary.
    """
    import zarr

    path = store_path(partial)
    group = zarr.open_group(path, mode="r+", zarr_format=FORMAT)
    group.attrs.update(json_safe(extra_attrs))
    zarr.consolidate_metadata(str(path), zarr_format=FORMAT)
    tag = secrets.token_hex(4)
    old = out.parent / f".{out.name}.old-{tag}"
    stale = sorted(out.parent.glob(f"{glob.escape(out.name)}.sensitivity-*"))
    stale += [p for p in map(Path, companions) if p.is_file() and p not in stale]
    with deferred_signals():
        aside = [p.parent / f".{p.name}.old-{tag}" for p in stale]
        for p, q in zip(stale, aside, strict=True):
            p.rename(q)
        moved = swap_in(path, out, aside=old)
    shutil.rmtree(partial, ignore_errors=True)
    if moved:
        shutil.rmtree(old, ignore_errors=True)
    for q in aside:
        q.unlink(missing_ok=True)


def check_target(out: Path) -> None:
    """Refuse to replace anything but an earlier sweep store."""
    if not out.exists():
        return
    attrs = out / ".zattrs"
    with contextlib.suppress(OSError, ValueError):
        if out.is_dir() and "ballscrew_version" in json.loads(attrs.read_text("utf-8")):
            return
    raise BallScrewInputError(
        "--out", str(out), "a new path or an earlier sweep store (it exists and is neither)"
    )


def percentile_variables(
    partial: Path,
    percentiles: Sequence[float],
    outputs: Mapping[str, tuple[str, str]],
    chunk_bytes: int = 1 << 25,
) -> dict[str, Any]:
    """Percentiles [%] over the samples of ``outputs`` (name -> unit, long name), read back.

    Streamed with dask: each block holds every sample of a block of the points
    after the sample dimension, about ``chunk_bytes`` in size.
    """
    import xarray as xr

    ds = xr.open_zarr(store_path(partial), consolidated=False)
    n = ds.sizes["sample"]
    budget = max(1, chunk_bytes // (8 * n))
    rechunk: dict[str, int] = {"sample": -1}
    inner = next((name for name in outputs if name in ds), None)
    after = ds[inner].dims[ds[inner].dims.index("sample") + 1 :] if inner else ()
    for name in reversed(after):
        rechunk[name] = max(1, min(ds.sizes[name], budget))
        budget = max(1, budget // rechunk[name])
    out = {}
    q = np.asarray(percentiles) / 100.0
    for name, (unit, long_name) in outputs.items():
        if name not in ds:
            continue
        value = ds[name].chunk(rechunk).quantile(q, dim="sample")
        value = value.rename(quantile="percentile")
        value.attrs = {"units": unit, "long_name": f"{long_name}: percentiles "
                       "over the Monte Carlo samples"}  # fmt: skip
        out[f"{name}_percentile"] = value.compute(scheduler="threads").variable
    out["percentile"] = xr.Variable("percentile", q * 100.0, {"units": "%"})
    return out


def mean_torque(partial: Path, over: Sequence[str]) -> Any:
    """Torque averaged over the dimensions ``over``, per model and sample (streamed)."""
    import xarray as xr

    ds = xr.open_zarr(store_path(partial), consolidated=False)
    return ds["torque"].mean(dim=list(over)).compute(scheduler="threads").values


def sobol_variables(names: Sequence[str], indices: Sequence[Any]) -> dict[str, Any]:
    """Sobol indices per model and input, with their 95 % half-widths, as variables."""
    import xarray as xr

    dims = ("model", "input")
    attrs = {"units": "1", "output": "torque averaged over the operating points",
             "confidence": "95 % bootstrap half-width (SALib)"}  # fmt: skip
    out = {}
    for key, label in (
        ("first", "first-order Sobol index"),
        ("first_conf", "first-order Sobol index: 95 % half-width"),
        ("total", "total Sobol index"),
        ("total_conf", "total Sobol index: 95 % half-width"),
    ):
        values = np.array([getattr(s, key) for s in indices])
        out[f"sobol_{key}"] = xr.Variable(dims, values, {**attrs, "long_name": label})
    out["input"] = xr.Variable("input", np.array(list(names), dtype=object))
    return out
