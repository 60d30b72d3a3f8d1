"""Loaders shared by the Du 2022 ch. 3 rule scripts (du2022_fda_*, du2022_fig3_*,
du2022_table3_1): the canonical primitives, the curve files, the saved SFPCA models,
torch's thread count."""

from __future__ import annotations

from pathlib import Path


def setup_threads(snakemake) -> None:
    """torch's intra-op threads = the job's, without importing torch: only the methods that
    need it import it (SFPCA, the GPLVM), and torch reads ``OMP_NUM_THREADS`` when it starts."""
    import os
    import sys

    n = max(int(snakemake.threads), 1)
    os.environ["OMP_NUM_THREADS"] = str(n)
    if "torch" in sys.modules:
        sys.modules["torch"].set_num_threads(n)


def canonical(snakemake):
    """The canonical (time-warped) primitives written by rule du2022_fda_canonical."""
    from _rule import dataset

    return dataset(snakemake.input.clips)


def load_curves(paths) -> list[dict]:
    """The arrays of each du2022_fda_curves file (motionvar.du2022.fda.evaluations.curves)."""
    import numpy as np

    out = []
    for path in paths:
        with np.load(path, allow_pickle=False) as z:
            out.append({k: z[k] for k in z.files})
    return out


def load_sfpca(paths) -> dict:
    """{primitive: SFPCA} of rule du2022_fda_sfpca's files (``<primitive>.npz`` + ``.json``)."""
    from motionvar.du2022.fda import SFPCA

    paths = [paths] if isinstance(paths, str) else list(paths)
    return {Path(p).stem: SFPCA.load(p) for p in paths if str(p).endswith(".npz")}
