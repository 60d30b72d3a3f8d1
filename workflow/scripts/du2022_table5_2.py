"""Rule du2022_table5_2 (Du 2022 Sec. 5.4.5, Tables 5.2-5.3): pose_SD, V_SD and step_SD
(Eq. 5.13-5.15) of the training data, the neutral VAE and the six CVAEs, for walk left
and right stance."""


def main(snakemake) -> None:
    import pandas as pd
    from _rule import write_evaluation
    from _style import load_inputs, load_settings

    from motionvar.du2022.style import evaluate_table5_2, load_vae
    from motionvar.du2022.style.figures import draw_table5_2

    dataset, layout, space = load_inputs(snakemake)
    models = [load_vae(f) for f in [*snakemake.input.vaes, *snakemake.input.cvaes]]
    histories = [pd.read_csv(f) for f in snakemake.input.cvae_histories]
    result = evaluate_table5_2(dataset, layout, space, models, load_settings(snakemake), histories)
    write_evaluation(snakemake, result, draw_table5_2, dpi=120)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
