"""Shared by the Egges 2004 rule scripts: joint map, model and recordings, figures."""

from __future__ import annotations

from pathlib import Path


def joint_map(snakemake):
    from motionvar.core import cmu_joint_map
    from motionvar.io.joint_map_file import load_joint_map

    path = snakemake.params.joint_map
    return load_joint_map(path) if path else cmu_joint_map()


def model(snakemake):
    from motionvar.egges2004.pipeline import load_model

    return load_model(snakemake.input.model)


def recordings(snakemake, idle_model):
    """(training, held-out) analysed recordings per subject, from the prep dataset."""
    from motionvar.egges2004.pipeline import model_recordings
    from motionvar.io import load_dataset

    folder = Path(snakemake.input.clips).parent
    return model_recordings(idle_model, load_dataset(folder), joint_map(snakemake), str(folder))


def figure_subjects(idle_model, options) -> list[str]:
    return list(idle_model.databases)[: options["figure_subjects"]]


def save(fig, path) -> None:
    import matplotlib.pyplot as plt

    fig.savefig(path, dpi=110)
    plt.close(fig)
