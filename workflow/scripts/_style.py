"""Loader shared by the Du 2022 ch. 5 rule scripts: the rule's settings (params
``settings``, the config section ``du2022_style``), its torch threads, its dataset (input
``clips``), the feature joints of its rig (params ``joint_map``) and the trained feature
space (input ``autoencoder``, when the rule has one)."""


def load_settings(snakemake):
    """The rule's StyleSettings, from the config section it was given whole."""
    from _rule import config_settings

    return config_settings(snakemake, "du2022_style")


def load_inputs(snakemake):
    """(dataset, feature layout, FeatureSpace or None)."""
    from pathlib import Path

    import torch
    from _rule import joint_map

    from motionvar.du2022.style import FeatureSpace
    from motionvar.du2022.style.data import dataset_layout
    from motionvar.io import load_dataset

    torch.set_num_threads(snakemake.threads)
    dataset = load_dataset(Path(snakemake.input.clips).parent)
    layout = dataset_layout(dataset, joint_map(snakemake))
    space = FeatureSpace.load(snakemake.input.autoencoder) if hasattr(snakemake.input, "autoencoder") else None
    return dataset, layout, space
