"""Rule du2022_fig4_12 (Du 2022 Fig. 4.12): search errors of the k-means, GMM and median
trees, random sampling and brute force per primitive and constraint type; box plots,
mean evaluations, and the claims of Sec. 4.6.2."""


def main(snakemake) -> None:
    import pandas as pd
    from _rule import write_evaluation

    from motionvar.du2022.graph.evaluations import evaluate_fig4_12
    from motionvar.du2022.graph.figures import draw_fig4_12

    queries = pd.concat([pd.read_csv(p) for p in snakemake.input.queries], ignore_index=True)
    write_evaluation(snakemake, evaluate_fig4_12(queries), draw_fig4_12, float_format="%.6g")


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
