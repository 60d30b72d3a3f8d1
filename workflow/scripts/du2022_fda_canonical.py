"""Rule du2022_fda_canonical (Du 2022 Sec. 3.3.3 / 4.4.1): the primitives of the chosen
behaviours on a canonical timeline (DTW to the median-length clip of each primitive, or
linear resampling), written as a packed dataset."""


def main(snakemake) -> None:
    from pathlib import Path

    from _rule import config_settings

    from motionvar.du2022.fda import canonical_primitives
    from motionvar.io import load_dataset, save_dataset

    s = config_settings(snakemake, "du2022_fda")
    dataset = load_dataset(Path(snakemake.input.clips).parent)
    motions, metadata = canonical_primitives(dataset, s.behaviours, s.min_clips, s.time_warping)
    save_dataset(Path(snakemake.output.clips).parent, motions, metadata)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
