"""Shared by the Du 2022 ch. 3 rule scripts (du2022_fda_*, du2022_fig3_*, du2022_table3_1):
loading the canonical primitives as functional data, and figure helpers."""

from __future__ import annotations

from pathlib import Path

import numpy as np

METHOD_LABELS = {
    "fpca": "FPCA",
    "normalized_fpca": "normalized FPCA",
    "sfpca": "SFPCA",
    "gplvm": "Bayesian GPLVM",
}
METHOD_STYLES = {
    "fpca": dict(color="tab:blue", marker="o"),
    "normalized_fpca": dict(color="tab:orange", marker="s"),
    "sfpca": dict(color="tab:green", marker="^"),
    "gplvm": dict(color="tab:red", marker="D"),
}


def setup_threads(snakemake) -> None:
    import torch

    torch.set_num_threads(max(int(snakemake.threads), 1))


def canonical(snakemake):
    """The canonical (time-warped) primitives written by rule du2022_fda_canonical."""
    from motionvar.io import load_dataset

    return load_dataset(Path(snakemake.input.clips).parent)


def primitive_motions(dataset, primitive: str):
    """(motions, metadata rows) of one primitive; ValueError naming it when absent."""
    meta = dataset.metadata
    idx = np.flatnonzero(meta["primitive"].to_numpy() == primitive)
    if len(idx) == 0:
        known = ", ".join(sorted(meta["primitive"].unique()))
        raise ValueError(f"primitive {primitive!r} has no canonical clips (known: {known})")
    return [dataset.motion(int(i)) for i in idx], meta.iloc[idx].reset_index(drop=True)


def n_basis_of(path, primitive: str) -> int:
    import pandas as pd

    table = pd.read_csv(path)
    row = table[table["primitive"] == primitive]
    if len(row) != 1:
        raise ValueError(f"{path}: no basis size for primitive {primitive!r} (config fda.behaviours)")
    return int(row["n_basis"].iloc[0])


def functional(snakemake, primitive: str):
    """(FunctionalMotions, metadata) of one primitive with its chosen number of basis functions."""
    from motionvar.du2022.fda import FunctionalMotions

    motions, meta = primitive_motions(canonical(snakemake), primitive)
    return FunctionalMotions.from_motions(motions, n_basis_of(snakemake.input.n_basis, primitive)), meta


def sfpca(options, fd, n_components: int):
    """An unfitted SFPCA with the settings of config fda.sfpca for the clips ``fd``."""
    from motionvar.du2022.fda import SFPCA

    sf = options["sfpca"]
    per_basis = sf["eval_frames_per_basis"]
    n_eval = min(fd.n_frames, per_basis * fd.basis.n_basis) if per_basis else None
    return SFPCA(n_components, weight_groups=sf["weight_groups"], gradient=sf["gradient"], max_iter=sf["max_iter"],
                 tol=sf["tol"], n_eval_frames=n_eval)


def plain_log_ticks(ax, axis: str = "y") -> None:
    """Ticks of a log axis at 1, 2, 5 x 10^k, labelled as plain numbers (0.2, 0.5, 1, 2)."""
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    target = ax.yaxis if axis == "y" else ax.xaxis
    target.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
    target.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    target.set_minor_formatter(NullFormatter())


def save(fig, path) -> None:
    import matplotlib.pyplot as plt

    fig.savefig(path, dpi=110)
    plt.close(fig)
