"""Rule du2022_fig4_10 (Du 2022 Fig. 4.10): constrained motion generation with the
Morphable Graph: a walk following a floor path (graph walk, Algorithm 1) and reaching
targets with the picking primitive; each step seeded by the k-means tree and optimised
by Levenberg-Marquardt on Eq. 4.9, the next primitive chosen by the mean motions T steps
ahead, and the walk's steps optimised together (Algorithm 1, line 9). The table lists the
constraint errors that remain and each reach's log-likelihood."""


def main(snakemake) -> None:
    from _evaluation import evaluate

    from motionvar.du2022.graph.figures import animate_fig4_10

    result = evaluate(snakemake).result
    animate_fig4_10(result, snakemake.output.gif)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
