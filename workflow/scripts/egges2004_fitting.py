"""Rule egges2004_fitting (Egges 2004 Sec. 5.4.4, 7.1, Fig. 4-5): fitted animations
start at p and end at q exactly, and the pieces of a generated sequence join smoothly."""


def main(snakemake) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    from _egges2004 import model, save
    from motionvar.claims import write_claims
    from motionvar.egges2004 import fit_anim_part, synthesize_balance
    from motionvar.egges2004.experiments import FittingParams, fitting, subject_rng
    from motionvar.egges2004.figures import plot_fitted_animation

    o = snakemake.params.options
    m = model(snakemake)
    table, example, claim = fitting(m, FittingParams(**o["fitting"]), o["seed"])
    table.to_csv(snakemake.output.table, index=False)

    s = next(iter(example))
    ex = example[s]
    a = ex["original"]
    fitted = {r: fit_anim_part(a, 0, len(a) - 1, ex["p"], ex["q"], r)[:, 0] for r in ("linear", "smoothstep")}
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2), gridspec_kw={"width_ratios": [1, 1.6, 1]})
    plot_fitted_animation(axes[0], a[:, 0], fitted, ex["p"][0], ex["q"][0], ex["fps"])
    axes[0].set_title(f"Fig. 4: a database shift fitted to new ends (subject {s})", fontsize=9)
    db = m.databases[s]
    seq, events = synthesize_balance(db, int(round(60 * db.fps)) + 1, subject_rng(o["seed"], s, "figure"))
    t = np.arange(len(seq)) / db.fps
    axes[1].plot(t, seq[:, 0], color="0.2", lw=1)
    for e in events:
        if e.kind == "shift":
            axes[1].axvspan(e.start / db.fps, e.stop / db.fps, color="tab:orange", alpha=0.3, lw=0)
    axes[1].set_xlabel("time (s)")
    axes[1].set_ylabel("PC 1")
    axes[1].set_title("60 s of balance shifting: rests and fitted shifts (shaded) join without jumps", fontsize=9)
    sub = table[table.test.str.startswith("fitAnim")]
    for ramp, off in (("linear", -0.2), ("smoothstep", 0.2)):
        rows = sub[sub.ramp == ramp]
        axes[2].bar(np.arange(len(rows)) + off, rows["max_junction_step_ratio"], 0.4, label=f"{ramp} offset")
    axes[2].axhline(1.0, color="tab:red", ls="--", lw=1, label="99 % quantile inside recorded shifts")
    axes[2].set_xticks(np.arange(len(sub.subject.unique())), sub.subject.unique(), fontsize=7)
    axes[2].set_xlabel("subject")
    axes[2].set_ylabel("largest junction step / recorded step")
    axes[2].legend(fontsize=8)
    axes[2].set_title("continuity at the junctions", fontsize=9)
    fig.tight_layout()
    save(fig, snakemake.output.figure)
    write_claims(snakemake.output.claims, [claim])


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
