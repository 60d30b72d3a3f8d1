"""Shared by the Du 2022 ch. 5 rule scripts (style_*.py, du2022_table5_*.py, du2022_fig5_4.py):
the rule's torch threads, its dataset (input ``clips``), the feature joints of the
dataset's rig (params ``joint_map``) and, when the rule has one, the trained feature space
(input ``autoencoder``)."""

from __future__ import annotations


def load_inputs(snakemake):
    """(config.style, dataset, feature layout, FeatureSpace or None)."""
    from pathlib import Path

    import torch

    from motionvar.core import cmu_joint_map
    from motionvar.io import load_dataset
    from motionvar.io.joint_map_file import load_joint_map
    from motionvar.du2022.style import FeatureSpace
    from motionvar.du2022.style.data import dataset_layout

    torch.set_num_threads(snakemake.threads)
    path = snakemake.params.joint_map
    dataset = load_dataset(Path(snakemake.input.clips).parent)
    layout = dataset_layout(dataset, load_joint_map(path) if path else cmu_joint_map())
    space = FeatureSpace.load(snakemake.input.autoencoder) if hasattr(snakemake.input, "autoencoder") else None
    return snakemake.params.cfg, dataset, layout, space
