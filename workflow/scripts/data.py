"""Rule data: generate the synthetic dataset or import a labelled BVH folder, and pack
it into results/{dataset}/data/ (clips.npz + metadata.csv)."""

from pathlib import Path


def load(entry: dict, workers: int = 1):
    """(motions, metadata) of one config.datasets entry; the generator runs ``workers``
    processes (the rule's threads; the output does not depend on it)."""
    if entry["source"] == "synthetic":
        from motionvar.synth import SynthSpec, generate_dataset

        return generate_dataset(SynthSpec(**{k: v for k, v in entry.items() if k != "source"}), workers=workers)
    from motionvar.core import cmu_joint_map
    from motionvar.io.bvh_dataset import import_bvh_folder
    from motionvar.io.joint_map_file import load_joint_map

    joint_map = load_joint_map(entry["joint_map"]) if entry["joint_map"] else cmu_joint_map()
    return import_bvh_folder(entry["path"], entry["labels"], entry["unit_cm"],
                             drop_first_frame=entry["drop_first_frame"], joint_map=joint_map)


def main(snakemake) -> None:
    import logging

    from motionvar.io import save_dataset

    try:
        motions, metadata = load(dict(snakemake.params.entry), workers=snakemake.threads)
    except ValueError as exc:
        raise ValueError(f"datasets.{snakemake.wildcards.dataset}: {exc}") from exc
    save_dataset(Path(snakemake.output.clips).parent, motions, metadata)
    logging.info("%s: %d clips, %d frames", snakemake.wildcards.dataset, len(motions), sum(m.n_frames for m in motions))


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
