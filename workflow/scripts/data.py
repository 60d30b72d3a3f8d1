"""Rule data: the synthetic generator or a labelled BVH folder, through the sanity gates
(motionvar.io.plausibility), packed into results/{dataset}/data/ (clips.npz + metadata.csv)."""

import logging
from pathlib import Path

from motionvar.core import cmu_joint_map
from motionvar.io import import_bvh_folder, save_dataset
from motionvar.io.joint_map_file import rig_joint_map
from motionvar.io.plausibility import plausibility_gate

KEYS = ("drop_first_frame", "behaviour_aliases", "style_aliases", "neutral_style", "mixed_rigs", "primitive_labels")


def load(entry: dict, workers: int = 1):
    """(motions, metadata, joint map) of a config.datasets entry; ``workers``: the generator's processes."""
    if entry["source"] == "synthetic":
        from motionvar.synth import SynthSpec, generate_dataset  # imported only for synthetic data

        spec = SynthSpec(**{k: v for k, v in entry.items() if k != "source"})
        return (*generate_dataset(spec, workers=workers), cmu_joint_map())
    jm = rig_joint_map(entry["joint_map"])
    kw = {k: entry[k] for k in KEYS if k in entry}
    return (*import_bvh_folder(entry["path"], entry["labels"], entry["unit_cm"], joint_map=jm, **kw), jm)


def main(snakemake) -> None:
    entry, name = dict(snakemake.params.entry), snakemake.wildcards.dataset
    try:
        motions, metadata, joint_map = load(entry, workers=snakemake.threads)
        plausibility_gate(motions, metadata, joint_map, entry.get("unit_cm"), entry.get("plausibility_check", True))
    except ValueError as exc:
        raise ValueError(f"datasets.{name}: {exc}") from exc
    save_dataset(Path(snakemake.output.clips).parent, motions, metadata)
    logging.info("%s: %d clips, %d frames", name, len(motions), sum(m.n_frames for m in motions))


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
