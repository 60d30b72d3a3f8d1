"""Shared by the Morphable Graph rule scripts (Du 2022 ch. 4): config -> library options,
clips of one primitive, joint map, models, figure saving."""

from __future__ import annotations

from pathlib import Path


def joint_map(snakemake):
    from motionvar.core import cmu_joint_map
    from motionvar.io.joint_map_file import load_joint_map

    path = snakemake.params.joint_map
    return load_joint_map(path) if path else cmu_joint_map()


def primitive_options(options: dict):
    from motionvar.du2022.graph import PrimitiveOptions

    m = options["model"]
    return PrimitiveOptions(
        n_basis=m["n_basis"], n_components=m["n_components"], gmm_components=(m["gmm_min"], m["gmm_max"]),
        gmm_criterion=m["gmm_criterion"], reg_covar=m["reg_covar"], sfpca_max_iter=m["sfpca_max_iter"],
        sfpca_weight_groups=m["sfpca_weight_groups"], sfpca_eval_frames=m["sfpca_eval_frames"], seed=options["seed"],
    )


def primitive_clips(clips_path: str, primitive: str):
    """(motions, metadata rows) of one primitive from a packed dataset; ValueError naming
    the file and the primitives it has when there are too few."""
    from motionvar.io import load_dataset

    ds = load_dataset(Path(clips_path).parent)
    mask = (ds.metadata["primitive"] == primitive).to_numpy()
    if mask.sum() < 3:
        have = ds.metadata["primitive"].value_counts().to_dict()
        raise ValueError(f"{clips_path}: {int(mask.sum())} clips of primitive {primitive!r} (need >= 3; config "
                         f"graph.primitives / graph.search.primitives); clips per primitive: {have}")
    pairs = ds.select(mask)
    return [m for _, m in pairs], ds.metadata[mask].reset_index(drop=True)


def semantic_index(jm, skeleton, semantic: str, key: str) -> int:
    if semantic not in jm.joints:
        raise KeyError(f"config {key}: {semantic!r} is not a semantic joint of the joint map "
                       f"({', '.join(sorted(jm.joints))})")
    return jm.index(skeleton, semantic)


def load_model(path: str):
    from motionvar.du2022.graph import MotionPrimitive

    return MotionPrimitive.load(path)


def save(fig, path: str) -> None:
    import matplotlib.pyplot as plt

    fig.savefig(path, dpi=110)
    plt.close(fig)
