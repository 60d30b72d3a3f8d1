"""Rule egges2004_repetition (Egges 2004 Sec. 6): repetition of generated small
variations and idle motion vs recorded motion and loops, and a PC curve with its
extrema (Fig. 7-8)."""


def main(snakemake) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    from _egges2004 import figure_subjects, model, recordings, save
    from motionvar.claims import write_claims
    from motionvar.egges2004 import find_extrema
    from motionvar.egges2004.experiments import RepetitionParams, repetition
    from motionvar.egges2004.figures import plot_pc_extrema, plot_repetition

    o = snakemake.params.options
    m = model(snakemake)
    train, _ = recordings(snakemake, m)
    params = RepetitionParams(**o["repetition"], perlin_frequency_hz=o["perlin_frequency_hz"])
    table, pooled, claim = repetition(m, train, params, o["seed"])
    table.to_csv(snakemake.output.table, index=False)
    fig, ax = plt.subplots(figsize=(10, 4.6))
    plot_repetition(ax, pooled)
    ax.set_title(f"Repetition within {params.sequence_s:g}-s sequences ({params.window_s:g}-s windows, "
                 f"first {m.databases[next(iter(m.databases))].variations.pcs.size} PCs)", fontsize=10)
    fig.tight_layout()
    save(fig, snakemake.output.figure)
    write_claims(snakemake.output.claims, [claim])

    shown = figure_subjects(m, o)
    pc, eps_sd = o["extrema_pc"] - 1, o["analysis"]["extrema_eps_sd"]
    fig, axes = plt.subplots(len(shown), 1, figsize=(10, 3.2 * len(shown)), squeeze=False)
    for ax, s in zip(axes[:, 0], shown):
        db = m.databases[s]
        rests = [(r, a, b) for r in train[s] for a, b in db.segments[r.name][0]]
        r, a, b = max(rests, key=lambda x: x[2] - x[1])
        x = r.pcs[a:b, pc]
        sd = np.sqrt(np.mean(np.concatenate([q.pcs[i:j, pc] - q.pcs[i:j, pc].mean() for q, i, j in rests]) ** 2))
        idx, is_max = find_extrema(x - x.mean(), eps_sd * sd)
        plot_pc_extrema(ax, x, db.fps, idx, is_max, pc)
        ax.set_title(f"subject {s}, clip {r.name}: longest resting segment, epsilon = {eps_sd:g} SD", fontsize=9)
    fig.tight_layout()
    save(fig, snakemake.output.extrema)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
