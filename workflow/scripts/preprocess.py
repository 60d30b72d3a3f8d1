"""Rule preprocess: foot contacts, segmentation into primitives and alignment of a
packed dataset (motionvar.prep), written to results/{dataset}/prep/."""


def main(snakemake) -> None:
    import logging
    from pathlib import Path

    from motionvar.core import cmu_joint_map
    from motionvar.io import load_dataset, save_dataset
    from motionvar.io.joint_map_file import load_joint_map
    from motionvar.prep import PrepOptions, preprocess_dataset

    try:
        options = PrepOptions.from_dict(snakemake.params.options)
    except ValueError as exc:
        raise ValueError(f"config prep: {exc}") from exc
    path = snakemake.params.joint_map
    joint_map = load_joint_map(path) if path else cmu_joint_map()
    dataset = load_dataset(Path(snakemake.input.clips).parent)
    motions, metadata = preprocess_dataset(dataset, joint_map, options)
    save_dataset(Path(snakemake.output.clips).parent, motions, metadata)
    logging.info("%d clips in, %d primitives out", len(dataset), len(motions))


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
