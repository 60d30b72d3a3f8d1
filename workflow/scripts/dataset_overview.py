"""Rule dataset_overview: key frames of one clip per behaviour and per walking style."""


def main(snakemake) -> None:
    from pathlib import Path

    import matplotlib.pyplot as plt
    from _rule import config_settings

    from motionvar.io import load_dataset
    from motionvar.plots import dataset_overview

    dataset = load_dataset(Path(snakemake.input.clips).parent)
    fig = dataset_overview(
        dataset,
        n_keys=config_settings(snakemake, "report").overview_key_frames,
        title=f"Dataset '{snakemake.wildcards.dataset}'",
    )
    fig.savefig(snakemake.output[0], dpi=110)
    plt.close(fig)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
