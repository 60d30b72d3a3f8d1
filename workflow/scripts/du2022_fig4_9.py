"""Rule du2022_fig4_9 (Du 2022 Fig. 4.9): end-effector positions at the last frame of
random motions of walk leftStance (left foot) and pick reach (both hands) against the
training clips, as 2-D kernel densities in three projections, with a coverage number."""


def main(snakemake) -> None:
    from _graph import dataset, models
    from _rule import config_settings, joint_map, write_evaluation

    from motionvar.du2022.graph.evaluations import evaluate_fig4_9
    from motionvar.du2022.graph.figures import draw_fig4_9

    settings = config_settings(snakemake, "graph")
    clips = snakemake.input.clips
    result = evaluate_fig4_9(
        models(snakemake.input.models), dataset(clips), joint_map(snakemake), settings, source=clips
    )
    write_evaluation(snakemake, result, draw_fig4_9, float_format="%.6g")


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
