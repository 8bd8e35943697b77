"""The Zarr store of a sweep: layout and attributes, resume markers, statistics, the final rename.

The store is Zarr format 2 with consolidated metadata, read back with
``xarray.open_zarr(path)``. Its attributes carry the sweep file's text, the
case file's text, the resolved screw and lubricant, every model's parameters
(defaults filled in), the unit of every variable and the package version.
"""

from __future__ import annotations

import contextlib
import json
import secrets
import shutil
from collections.abc import Sequence
from dataclasses import asdict
from pathlib import Path
from typing import Any, Literal

import numpy as np

from .._version import __version__
from ..errors import BallScrewInputError
from ..friction import get_model
from ..io.files import swap_in
from .spec import OPERATING, OUTPUT_TABLE, OUTPUTS, SCALAR_OUTPUTS

__all__ = ["FORMAT", "attributes", "create", "finalize", "markers", "partial_path"]

FORMAT: Literal[2] = 2
"""Zarr format: 2 stores text coordinates (model and component names) in a
stable, specified way, and consolidated metadata; both are still unstable
extensions in format 3."""

FINGERPRINT = "fingerprint"

LONG_NAMES = {
    **{o.name: o.long_name for o in OUTPUT_TABLE},
    "speed": "screw speed",
    "temperature": "lubricant temperature",
    "axial_load": "external axial load on the nut",
}


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


def _json_safe(value: Any) -> Any:
    if isinstance(value, dict):
        return {str(k): _json_safe(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_json_safe(v) for v in value]
    if isinstance(value, np.generic):
        return value.item()
    if value is None or isinstance(value, str | int | float | bool):
        return value
    return str(value)


def attributes(plan: Any) -> dict[str, Any]:
    """The store's attributes: inputs, units, parameters, version."""
    spec = plan.spec
    units: dict[str, str] = {name: OUTPUTS[name] for name in spec.outputs}
    units |= {name: unit for name, unit in OPERATING.items()}
    units |= {a.name: a.unit for a in spec.axes}
    parameters = {}
    for model in spec.models:
        used = dict(get_model(model).parameters)
        used.update(plan.parameters[model])
        parameters[model] = used
    attrs: dict[str, Any] = {
        "title": f"ballscrew sweep: {spec.case.title}",
        "ballscrew_version": __version__,
        "sweep_file": spec.source,
        "sweep_toml": spec.text,
        "case_toml": spec.case.text,
        "models": list(spec.models),
        "model_parameters": parameters,
        "units": units,
        "screw": asdict(spec.case.screw),
        "lubricant": asdict(spec.case.lubricant),
        "axes": {a.name: a.unit for a in spec.axes},
        "chunk_points": spec.chunk_points,
        "conventions": "SI units (temperatures in degC); speed > 0 turns the screw forward",
    }
    u = spec.uncertainty
    if u is not None:
        units |= {d.name: d.unit or "1" for d in u.inputs}
        attrs["uncertainty"] = {
            "inputs": {d.name: d.describe() for d in u.inputs},
            "samples": u.samples,
            "seed": u.seed,
            "sensitivity": u.sensitivity,
            "design": (
                "Saltelli/Sobol' (SALib sobol.sample, no second order): N (D + 2) rows"
                if u.sensitivity == "sobol"
                else "Latin hypercube (SALib latin.sample)"
            ),
        }
    return _json_safe(attrs)  # type: ignore[no-any-return]


def _dataset(plan: Any) -> Any:
    """The layout as an xarray Dataset of lazy NaN arrays (nothing is computed)."""
    import dask.array as da
    import xarray as xr

    spec = plan.spec
    n_outer = len(plan.outer)
    coords: dict[str, Any] = {"model": np.array(spec.models, dtype=object)}
    for axis in spec.axes:
        labels = axis.labels
        values = np.array(axis.values, dtype=object if labels else float)
        coords[axis.name] = xr.Variable(axis.name, values, {"units": axis.unit})
    if plan.samples is not None:
        coords["sample"] = np.arange(plan.samples.shape[0])
        for j, dist in enumerate(spec.uncertainty.inputs):
            attrs = {"units": dist.unit or "1", "distribution": dist.describe()}
            coords[dist.name] = xr.Variable("sample", plan.samples[:, j], attrs)
    for name, unit in OPERATING.items():
        attrs = {"units": unit, "long_name": LONG_NAMES[name]}
        coords[name] = xr.Variable(name, spec.operating[name], attrs)
    coords["speed_rpm"] = xr.Variable("speed", spec.operating["speed"] * 30.0 / np.pi,
                                      {"units": "rpm"})  # fmt: skip
    data: dict[str, Any] = {}
    for name in spec.outputs:
        dims, shape, chunks = plan.dims, plan.shape, plan.chunks
        if name == "components":
            cut = 1 + n_outer
            dims = (*dims[:cut], "component", *dims[cut:])
            shape = (*shape[:cut], len(plan.components), *shape[cut:])
            chunks = (*chunks[:cut], len(plan.components), *chunks[cut:])
        attrs = {"units": OUTPUTS[name], "long_name": LONG_NAMES[name]}
        data[name] = xr.Variable(dims, da.full(shape, np.nan, chunks=chunks), attrs)
    if "components" in spec.outputs:
        coords["component"] = np.array(plan.components, dtype=object)
    return xr.Dataset(data, coords=coords, attrs=attributes(plan))


def create(plan: Any, partial: Path, fingerprint: str) -> None:
    """Write the layout (coordinates, attributes, empty arrays) and the fingerprint."""
    if partial.exists():
        shutil.rmtree(partial)
    dataset = _dataset(plan)
    encoding = {name: {"chunks": dataset[name].data.chunksize} for name in plan.spec.outputs}
    dataset.to_zarr(store_path(partial), mode="w", compute=False, consolidated=False,
                    zarr_format=FORMAT, encoding=encoding)  # fmt: skip
    progress_path(partial).mkdir()
    (progress_path(partial) / FINGERPRINT).write_text(fingerprint, encoding="utf-8")


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


def finalize(partial: Path, out: Path, extra_attrs: dict[str, Any]) -> None:
    """Consolidate the metadata, rename the store to ``out`` and drop the partial folder."""
    import zarr

    path = store_path(partial)
    group = zarr.open_group(path, mode="r+", zarr_format=FORMAT)
    group.attrs.update(_json_safe(extra_attrs))
    zarr.consolidate_metadata(str(path), zarr_format=FORMAT)
    old = out.parent / f".{out.name}.old-{secrets.token_hex(4)}"
    moved = swap_in(path, out, aside=old)
    shutil.rmtree(partial, ignore_errors=True)
    if moved:
        shutil.rmtree(old, ignore_errors=True)


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


def percentile_variables(partial: Path, plan: Any, chunk_bytes: int = 1 << 25) -> dict[str, Any]:
    """Percentiles over the samples of torque and efficiency, read back from the store.

    Streamed with dask: each block holds every sample of a block of operating
    points, about ``chunk_bytes`` in size.
    """
    import xarray as xr

    u = plan.spec.uncertainty
    ds = xr.open_zarr(store_path(partial), consolidated=False)
    n = ds.sizes["sample"]
    budget = max(1, chunk_bytes // (8 * n))
    rechunk: dict[str, int] = {"sample": -1}
    for name in reversed(OPERATING):
        rechunk[name] = max(1, min(ds.sizes[name], budget))
        budget = max(1, budget // rechunk[name])
    out = {}
    q = np.asarray(u.percentiles) / 100.0
    for name in (o.name for o in SCALAR_OUTPUTS):
        if name not in ds:
            continue
        value = ds[name].chunk(rechunk).quantile(q, dim="sample")
        value = value.rename(quantile="percentile")
        value.attrs = {"units": OUTPUTS[name], "long_name": f"{LONG_NAMES[name]}: percentiles "
                       "over the Monte Carlo samples"}  # fmt: skip
        out[f"{name}_percentile"] = value.compute(scheduler="threads").variable
    out["percentile"] = xr.Variable("percentile", q * 100.0, {"units": "%"})
    return out


def mean_torque(partial: Path) -> Any:
    """Torque averaged over the operating points, per model and sample (streamed)."""
    import xarray as xr

    ds = xr.open_zarr(store_path(partial), consolidated=False)
    return ds["torque"].mean(dim=list(OPERATING)).compute(scheduler="threads").values


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
