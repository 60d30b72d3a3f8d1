"""Rule preprocess: foot contacts, segmentation into primitives and alignment of a
packed dataset (motionvar.prep), written to results/{dataset}/prep/; the primitives and
clips dropped (too short, none found) are counted in the log and listed in dropped.csv."""


def main(snakemake) -> None:
    import logging
    from pathlib import Path

    from _rule import config_settings, joint_map

    from motionvar.io import load_dataset, save_dataset
    from motionvar.prep import drop_summary, preprocess_dataset

    try:
        options = config_settings(snakemake, "prep")
    except ValueError as exc:
        raise ValueError(f"config prep: {exc}") from exc
    name = snakemake.wildcards.dataset
    dataset = load_dataset(Path(snakemake.input.clips).parent)
    result = preprocess_dataset(dataset, joint_map(snakemake), options, name=name)
    prep = Path(snakemake.output.clips).parent
    save_dataset(prep, result.motions, result.metadata)
    result.dropped.to_csv(getattr(snakemake.output, "dropped", prep / "dropped.csv"), index=False, float_format="%.6g")
    summary = drop_summary(result, len(dataset), name, options.min_primitive_s)
    (logging.warning if len(result.dropped) else logging.info)("%s", summary)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
