"""Rule du2022_fig3_9 (Du 2022 Fig. 3.9, Sec. 3.3.3): joint-space RMSE between the B-spline
functions and the canonical frames for an increasing number of basis functions K, per
behaviour and per primitive with the K chosen by the cut-off rule (from du2022_fda_basis)."""


def main(snakemake) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    import pandas as pd

    from _du2022_fda import plain_log_ticks, save
    from motionvar.claims import Claim, verdict_from_fraction, write_claims

    o = snakemake.params.options["basis"]
    table = pd.read_csv(snakemake.input.rmse)
    chosen = table[table["chosen"]].to_dict("records")

    # per behaviour: RMSE pooled over its primitives' clips and frames
    table["weight"] = table["n_clips"] * table["canonical_frames"]
    table["sq"] = table["rmse_cm"] ** 2 * table["weight"]
    pooled = table.groupby(["behaviour", "n_basis"])[["sq", "weight"]].sum()
    pooled = np.sqrt(pooled["sq"] / pooled["weight"]).rename("rmse_cm").reset_index()
    table = table.drop(columns=["weight", "sq"])
    behaviour_rows = pooled.assign(primitive="(all)", chosen=False)
    out = pd.concat([table, behaviour_rows], ignore_index=True)
    out.to_csv(snakemake.output.table, index=False, float_format="%.6g")

    fig, axes = plt.subplots(1, 2, figsize=(12, 4.6))
    for behaviour, g in pooled.groupby("behaviour"):
        axes[0].plot(g["n_basis"], g["rmse_cm"], marker="o", label=behaviour)
    axes[0].set(title="Per behaviour (pooled over its primitives)", xlabel="number of basis functions K",
                ylabel="joint-space RMSE (cm)", yscale="log")
    axes[0].legend(fontsize=8)
    palette = plt.cm.tab20.colors  # dark tones first, then the light ones: 20 distinct colours
    for i, (primitive, g) in enumerate(table.groupby("primitive")):
        color = palette[(2 * i) % 20 + (2 * i // 20) % 2]
        axes[1].plot(g["n_basis"], g["rmse_cm"], marker=".", lw=1, label=primitive, color=color)
        c = g[g["chosen"]]
        axes[1].plot(c["n_basis"], c["rmse_cm"], "o", ms=9, mfc="none", color=color)
    axes[1].set(title=f"Per primitive (circle: chosen K, cut-off {o['min_relative_drop']:.0%} per added function)",
                xlabel="number of basis functions K", ylabel="joint-space RMSE (cm)", yscale="log")
    axes[1].legend(fontsize=7, ncol=2)
    for ax in axes:
        ax.grid(alpha=0.3, which="both")
        plain_log_ticks(ax)
    fig.suptitle("Du 2022 Fig. 3.9: cubic B-spline representation of canonical clips", fontsize=11)
    fig.tight_layout()
    save(fig, snakemake.output.figure)

    decreasing = {b: bool(np.all(np.diff(g["rmse_cm"].to_numpy()) < 0)) for b, g in pooled.groupby("behaviour")}
    n_ok = sum(decreasing.values())
    ks = sorted(pooled["n_basis"].unique())
    measured = "; ".join(
        f"{b}: {g['rmse_cm'].iloc[0]:.3g} cm (K={ks[0]}) -> {g['rmse_cm'].iloc[-1]:.3g} cm (K={g['n_basis'].iloc[-1]})"
        + ("" if decreasing[b] else " (not monotone)")
        for b, g in pooled.groupby("behaviour")
    )
    claim = Claim(
        claim_id="du2022.fig3_9.rmse_decreases_with_k",
        paper="du2022",
        source="Fig. 3.9",
        statement="The joint-space RMSE of the cubic B-spline representation decreases as the number of "
        "basis functions K grows, for every motion type.",
        published="RMSE falls with K for every motion type (curves in Fig. 3.9); chosen K: walk 10, "
        "two-hand pick 25, carry 15, transfer 20 (Table 3.1)",
        measured=f"{n_ok}/{len(decreasing)} behaviours strictly decreasing; {measured}; chosen K: "
        + ", ".join(f"{c['primitive']} {c['n_basis']}" for c in chosen),
        verdict=verdict_from_fraction(n_ok, len(decreasing)),
        note="RMSE of FK joint positions between the B-spline functions evaluated at the canonical "
        "frames and the canonical (time-warped) frames themselves.",
    )
    write_claims(snakemake.output.claims, [claim])


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
