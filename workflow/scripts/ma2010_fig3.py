"""Rule ma2010_fig3 (Ma 2010 Fig. 3, Sec. 4.1): key frames of a walk and a run, and whether
the maxima of S_M(t) fall at one gait phase (motionvar.ma2010.evaluations.fig3)."""


def main(snakemake) -> None:
    from pathlib import Path

    from _ma2010 import settings
    from _rule import joint_map, write_evaluation

    from motionvar.io import load_dataset
    from motionvar.ma2010.evaluations.fig3 import fig3_keyframes
    from motionvar.ma2010.figures import draw_fig3

    result = fig3_keyframes(
        load_dataset(Path(snakemake.input.clips).parent),
        joint_map(snakemake),
        settings(snakemake),
        what=f"{snakemake.input.metadata} (config ma2010.walk_styles / walk_variants)",
    )
    write_evaluation(snakemake, result, draw_fig3)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
