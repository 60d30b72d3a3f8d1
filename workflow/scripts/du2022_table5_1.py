"""Rule du2022_table5_1 (Du 2022 Sec. 5.4.3, Table 5.1): style distance D(m, s) (Eq. 5.12)
between the samples of each model (neutral VAE, six CVAEs) and each style example."""


def main(snakemake) -> None:
    import pandas as pd
    from _rule import write_evaluation
    from _style import load_inputs, load_settings

    from motionvar.du2022.style import evaluate_table5_1, load_vae
    from motionvar.du2022.style.figures import draw_table5_1

    dataset, layout, space = load_inputs(snakemake)
    neutral = load_vae(snakemake.input.vaes[0])
    cvaes = [load_vae(f) for f in snakemake.input.cvaes]
    histories = [pd.read_csv(f) for f in snakemake.input.cvae_histories]
    result = evaluate_table5_1(dataset, layout, space, neutral, cvaes, load_settings(snakemake), histories)
    write_evaluation(snakemake, result, draw_table5_1, dpi=130)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
