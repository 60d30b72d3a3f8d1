"""Rule du2022_style_training_curves (Du 2022 Sec. 5.4.1): the training loss per epoch of the
autoencoder, the neutral VAEs and the CVAEs."""


def main(snakemake) -> None:
    from pathlib import Path

    import matplotlib.pyplot as plt
    import pandas as pd

    from motionvar.du2022.style.figures import draw_training

    def name(f):  # vae/<primitive>_history.csv, cvae/<primitive>/<style>_history.csv
        return Path(f).name.removesuffix("_history.csv")

    fig = draw_training(
        pd.read_csv(snakemake.input.autoencoder),
        {name(f): pd.read_csv(f) for f in snakemake.input.vaes},
        {(Path(f).parent.name, name(f)): pd.read_csv(f) for f in snakemake.input.cvaes},
    )
    fig.savefig(snakemake.output.figure, dpi=110)
    plt.close(fig)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
