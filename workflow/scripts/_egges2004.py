"""Loaders of the Egges 2004 rule scripts: the settings of config section egges2004, joint
map, fitted model, prep dataset and its analysed idle clips; and a figure writer."""

from pathlib import Path


def settings(snakemake):
    """The rule's Egges2004Settings, from the whole config section (params.settings)."""
    from _rule import config_settings

    return config_settings(snakemake, "egges2004")


def model(snakemake):
    from motionvar.egges2004.storage import load_idle_model

    return load_idle_model(snakemake.input.model)


def prep(snakemake):
    from motionvar.io import load_dataset  # (the prep dataset, its folder: named in errors)

    folder = Path(snakemake.input.clips).parent
    return load_dataset(folder), str(folder)


def recordings(snakemake, idle_model):  # (training, held-out) analysed recordings per subject
    from _rule import joint_map

    from motionvar.egges2004.pipeline import model_recordings

    dataset, source = prep(snakemake)
    return model_recordings(idle_model, dataset, joint_map(snakemake), source)


def save_figure(fig, path) -> None:
    import matplotlib.pyplot as plt

    fig.savefig(path, dpi=110)
    plt.close(fig)
