"""Build the helix's traction tables at every aspect node: ``src/ballscrew/data/helix_tables.npz``.

    .venv/bin/python scripts/build_helix_tables.py

:func:`ballscrew.helix._tables` interpolates the tables of J/(1+sigma) and G
(:func:`ballscrew.rolling_losses.spin_slip_integrals` at kappa = 0 over the
``TABLE_NODES`` values of t = sigma/(1+sigma)) across ``ASPECT_NODES`` ellipse aspects
from 0 to 1. Each node costs 8 ms of quadrature; a new process needs the four around each
contact's aspect. Stored, they cost a 2 MB file read once. The file is rebuilt here from
the package's own quadrature whenever the rule, the nodes or the integrals change;
``tests/physics/test_helix.py`` checks that it still equals a fresh build.
"""

from __future__ import annotations

import numpy as np

from ballscrew import helix
from ballscrew.io.files import atomic_write


def main() -> None:
    """Build every node's tables and write them, atomically."""
    nodes = range(helix.ASPECT_NODES)
    built = [helix._exact_tables(i / (helix.ASPECT_NODES - 1)) for i in nodes]
    path = helix.TABLES_FILE
    import io

    buffer = io.BytesIO()
    np.savez(
        buffer,
        j=np.stack([j for j, _ in built]),
        g=np.stack([g for _, g in built]),
        table_nodes=np.array(helix.TABLE_NODES),
        aspect_nodes=np.array(helix.ASPECT_NODES),
    )
    atomic_write(path, buffer.getvalue())
    print(f"{path}: {helix.ASPECT_NODES} aspects x {helix.TABLE_NODES} nodes")


if __name__ == "__main__":
    main()
