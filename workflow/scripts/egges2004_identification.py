"""Rule egges2004_identification (Egges 2004 Sec. 5.6, 8): does generated idle motion
identify its person? A classifier trained on windows of each subject's recorded idle
clips names the subject of generated windows, of held-out recordings and of the Perlin
baseline."""


def main(snakemake) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from _egges2004 import joint_map, model, recordings, save
    from motionvar.claims import write_claims
    from motionvar.egges2004.experiments import IdentificationParams, identification
    from motionvar.egges2004.figures import plot_identification

    o = snakemake.params.options
    m = model(snakemake)
    train, held = recordings(snakemake, m)
    params = IdentificationParams(**o["identification"], perlin_frequency_hz=o["perlin_frequency_hz"])
    table, confusion, claim = identification(
        m, train, held, joint_map(snakemake), params, o["analysis"]["support_margin"], o["seed"]
    )
    table.to_csv(snakemake.output.table, index=False)
    fig, (a, b) = plt.subplots(1, 2, figsize=(12, 4.6), gridspec_kw={"width_ratios": [1.5, 1]})
    plot_identification(a, b, table, confusion)
    a.set_title(f"Who is it? {len(confusion['labels'])} subjects, {params.window_s:g}-s windows", fontsize=10)
    fig.tight_layout()
    save(fig, snakemake.output.figure)
    write_claims(snakemake.output.claims, [claim])


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
