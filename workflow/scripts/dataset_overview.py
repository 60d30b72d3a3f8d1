"""Rule dataset_overview: key frames of one clip per behaviour and per walking style."""


def main(snakemake) -> None:
    from pathlib import Path

    import matplotlib.pyplot as plt

    from motionvar.io import load_dataset
    from motionvar.plots import dataset_overview
    from motionvar.report.settings import ReportSettings

    dataset = load_dataset(Path(snakemake.input.clips).parent)
    fig = dataset_overview(
        dataset,
        n_keys=ReportSettings.from_dict(snakemake.params.settings).overview_key_frames,
        title=f"Dataset '{snakemake.wildcards.dataset}'",
    )
    fig.savefig(snakemake.output[0], dpi=110)
    plt.close(fig)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
