"""Rule style_training_curves (Du 2022 Sec. 5.4.1): the training loss per epoch of the
autoencoder, the neutral VAEs and the CVAEs."""


def main(snakemake) -> None:
    from pathlib import Path

    import matplotlib.pyplot as plt
    import pandas as pd

    from motionvar.du2022.style.figures import training_curves

    def name(f):
        p = Path(f)
        return p.stem.replace("_history", "") if p.parent.name in ("du2022_style", "vae") else f"{p.parent.name}/{p.stem.replace('_history', '')}"

    hist = {"autoencoder": pd.read_csv(snakemake.input.autoencoder)}
    groups = {"conv autoencoder (Eq. 5.1-5.2)": ["autoencoder"], "neutral VAEs (Eq. 5.6)": []}
    for f in snakemake.input.vaes:
        hist[name(f)] = pd.read_csv(f)
        groups["neutral VAEs (Eq. 5.6)"].append(name(f))
    for f in snakemake.input.cvaes:
        key = name(f)
        hist[key] = pd.read_csv(f)
        groups.setdefault(f"CVAEs {Path(f).parent.name} (Eq. 5.11)", []).append(key)
    fig = training_curves(hist, groups)
    fig.savefig(snakemake.output.figure, dpi=110)
    plt.close(fig)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
