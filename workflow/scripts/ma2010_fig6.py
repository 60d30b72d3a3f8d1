"""Rule ma2010_fig6 (Ma 2010 Fig. 6, Sec. 7.1): leave-one-out stride error over the walking
cycles (whole-walk or single-cycle folds), with the root rotation in the other joint group
as an ablation; Kriging vs RBF on the same folds (motionvar.ma2010.evaluations.fig6)."""


def main(snakemake) -> None:
    from _ma2010 import load_walks, settings
    from _rule import write_evaluation

    from motionvar.ma2010.evaluations.fig6 import fig6_leave_one_out
    from motionvar.ma2010.figures import draw_fig6

    s = settings(snakemake)
    result = fig6_leave_one_out(load_walks(snakemake, s), s)
    write_evaluation(snakemake, result, draw_fig6)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
