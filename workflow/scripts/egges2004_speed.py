"""Rule egges2004_speed (Egges 2004 Sec. 8): frames of idle motion generated per second
against the playback rate."""


def main(snakemake) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from _egges2004 import model, save
    from motionvar.claims import write_claims
    from motionvar.egges2004.experiments import SpeedParams, speed
    from motionvar.egges2004.figures import plot_speed

    o = snakemake.params.options
    table, claim = speed(model(snakemake), SpeedParams(**o["speed"]), o["seed"])
    table.to_csv(snakemake.output.table, index=False)
    fig, ax = plt.subplots(figsize=(7, 4))
    plot_speed(ax, table)
    ax.set_title(f"Idle motion generation, {o['speed']['sequence_s']:g}-s sequences (one core)", fontsize=10)
    fig.tight_layout()
    save(fig, snakemake.output.figure)
    write_claims(snakemake.output.claims, [claim])


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
