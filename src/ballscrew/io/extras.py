"""The optional parts of the package and the extras that install them.

A torque calculation needs only the core dependencies. Sweeps need the ``sweep``
extra (xarray, Zarr, Dask, distributed, SALib) and the web calculator the ``web``
extra (Starlette, uvicorn, AnyIO, Jinja2)::

    pip install 'ballscrew[sweep]'    # or [web], or [all] for both

A command or function whose extra is missing raises :class:`MissingExtraError`
(an :class:`ImportError`) naming the extra; the command line prints it as one
line and exits with status 2.

Examples
--------
>>> from ballscrew.io.extras import EXTRAS, missing
>>> EXTRAS["sweep"]
('xarray', 'zarr', 'dask', 'distributed', 'SALib')
>>> missing("sweep", modules=("math",)) is None
True
"""

from __future__ import annotations

import importlib.util
from collections.abc import Sequence

__all__ = ["EXTRAS", "MissingExtraError", "MissingExtraWarning", "missing", "require"]

EXTRAS: dict[str, tuple[str, ...]] = {
    "sweep": ("xarray", "zarr", "dask", "distributed", "SALib"),
    "web": ("starlette", "uvicorn", "anyio", "jinja2"),
    "fast": ("numba",),
    "program": ("ruckig", "xarray"),
    "servo": ("control",),
    "select": ("pymoo",),
}
"""The top-level modules each extra installs (the import names, not the distributions')."""


class MissingExtraError(ImportError):
    """A part of the package was used whose extra is not installed.

    Attributes
    ----------
    what : str
        The command or module that needs it (``"ballscrew sweep"``).
    extra : str
        The extra to install (``"sweep"``).
    """

    def __init__(self, what: str, extra: str, module: str) -> None:
        self.what = what
        self.extra = extra
        super().__init__(
            f"{what} needs the {extra} extra ({module} is not installed): "
            f"pip install 'ballscrew[{extra}]'",
            name=module,
        )


class MissingExtraWarning(UserWarning):
    """A part of a result was left out because its extra is not installed."""


def _absent(module: str) -> bool:
    try:
        return importlib.util.find_spec(module) is None
    except (ImportError, ValueError):  # a parent that does not import, or a broken entry
        return True


def missing(extra: str, modules: Sequence[str] | None = None) -> str | None:
    """The first module of ``extra`` (or of ``modules``, part of it) that is not installed.

    ``None`` when all are. Only looks for the modules, it does not import them.
    """
    for module in EXTRAS[extra] if modules is None else modules:
        if _absent(module):
            return module
    return None


def require(extra: str, what: str, modules: Sequence[str] | None = None) -> None:
    """Raise :class:`MissingExtraError` if a module of ``extra`` is not installed.

    Parameters
    ----------
    extra : str
        The extra, a key of :data:`EXTRAS`.
    what : str
        What needs it, as the message names it (``"ballscrew sweep"``).
    modules : sequence of str, optional
        The modules of the extra that are needed (all of them by default).
    """
    module = missing(extra, modules)
    if module is not None:
        raise MissingExtraError(what, extra, module)
