"""Loaders shared by the Ma 2010 rule scripts: the dataset's joint map and the walking
cycles written by rule ma2010_clips (motionvar.ma2010.examples.WalkCycles)."""

from __future__ import annotations

WALKS_DTYPES = {"clip_id": str, "subject": str, "source_clip": str}


def walks_source(snakemake) -> str:
    """How errors about the dataset's walking clips name it: its metadata and the config keys
    that select the walks."""
    return f"{snakemake.input.metadata} (config ma2010.clips.walk_styles / walk_variants)"


def settings(snakemake):
    """The rule's Ma2010Settings, built from its whole config section (params.settings)."""
    from _rule import config_settings

    return config_settings(snakemake, "ma2010")


def load_walks(snakemake, settings):
    """The cycles of input ``clips`` (ClipSet model file) with the subjects and walks of input
    ``table``; the root rotation in the joint group ``settings.model.root_group``."""
    import pandas as pd
    from _rule import joint_map

    from motionvar.io.model_file import load_model
    from motionvar.ma2010.examples import CLIPSET_KIND, WalkCycles
    from motionvar.ma2010.representation import ClipSet

    clips = ClipSet.from_arrays(load_model(snakemake.input.clips, kind=CLIPSET_KIND)[0])
    table = pd.read_csv(snakemake.input.table, dtype=WALKS_DTYPES)
    if len(table) != clips.n_clips or list(table["clip_id"]) != clips.clip_ids:
        raise ValueError(
            f"{snakemake.input.table} does not list the cycles of {snakemake.input.clips}; rerun ma2010_clips"
        )
    return WalkCycles(
        clips,
        table["subject"].tolist(),
        joint_map(snakemake),
        source=snakemake.input.table,
        root_group=settings.model.root_group,
        source_clips=table["source_clip"].tolist(),
    )
