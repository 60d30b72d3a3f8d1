"""Rule du2022_sec4_6_1 (Du 2022 Sec. 4.6.1, "Compactness"): bytes of the motion
primitive models against the bytes of the clips they were fitted to."""


def main(snakemake) -> None:
    import pandas as pd
    from _graph import model_bytes, models
    from _rule import write_evaluation

    from motionvar.du2022.graph.evaluations import evaluate_sec4_6_1
    from motionvar.du2022.graph.figures import draw_sec4_6_1

    paths, dense = snakemake.input.models, snakemake.input.dense
    result = evaluate_sec4_6_1(
        models(paths),
        model_bytes(paths),
        pd.read_csv(snakemake.input.metadata),
        pd.read_csv(dense[0]) if dense else None,
    )
    write_evaluation(snakemake, result, draw_sec4_6_1, float_format="%.6g")


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
