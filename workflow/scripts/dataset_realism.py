"""Rule dataset_realism: the dataset's realism statistics against the bands that captured
data gives them (motionvar.realism), a table, a per-joint channel table and a figure."""


def main(snakemake) -> None:
    from pathlib import Path

    import matplotlib.pyplot as plt
    from _rule import config_settings, joint_map

    from motionvar.io import load_dataset
    from motionvar.plots import realism_figure
    from motionvar.realism import dataset_realism, judge

    table, joints = dataset_realism(
        load_dataset(Path(snakemake.input.clips).parent),
        joint_map(snakemake),
        config_settings(snakemake, "prep"),
        config_settings(snakemake, "realism"),
    )
    table = judge(table)
    table.to_csv(snakemake.output.table, index=False, float_format="%.6g")
    joints.to_csv(snakemake.output.joints, index=False, float_format="%.6g")
    fig = realism_figure(
        table, joints, f"Dataset '{snakemake.wildcards.dataset}': how it varies, against captured data"
    )
    fig.savefig(snakemake.output.figure, dpi=110)
    plt.close(fig)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
