"""Rule du2022_fig4_9 (Du 2022 Fig. 4.9): end-effector positions at the last frame of
random motions of walk leftStance (left foot) and pick reach (both hands) against the
training clips, as 2-D kernel densities in three projections, with a coverage number."""

VIEWS = (("top (x, z)", 0, 2), ("side (x, y)", 0, 1), ("front (z, y)", 2, 1))
CASES = (("walk", "walk_leftStance", "left_ankle"), ("pick", "pick_reach", "left_hand"),
         ("pick", "pick_reach", "right_hand"))
AXIS = "xyz"


def main(snakemake) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    import pandas as pd

    from _graph import joint_map, load_model, primitive_clips, save, semantic_index
    from motionvar.claims import write_claims
    from motionvar.du2022.graph.evaluation import coverage
    from motionvar.du2022.graph.verdicts import fig4_9_claim

    o = snakemake.params.options
    d = o["diversity"]
    jm = joint_map(snakemake)
    models = {"walk": load_model(snakemake.input.walk), "pick": load_model(snakemake.input.pick)}
    rows, panels = [], []
    for key, prim, sem in CASES:
        model = models[key]
        j = semantic_index(jm, model.skeleton, sem, "graph diversity joints")
        S = model.sample(d["n_samples"], np.random.default_rng([o["seed"], 49]))
        pos = np.concatenate([model.key_frame_pose(S[i:i + 10000], [model.n_frames - 1], [j])[0][:, 0, 0]
                              for i in range(0, len(S), 10000)])
        motions, _ = primitive_clips(snakemake.input.clips, prim)
        train = np.stack([m.positions()[-1, j] for m in motions])
        for view, a, b in VIEWS:
            cov, thr, data = coverage(pos[:, [a, b]], train[:, [a, b]], d["level"], d["grid"])
            rows.append(dict(primitive=prim, joint=sem, view=view, coverage=cov, n_training=len(train),
                             n_samples=len(pos)))
            panels.append((prim, sem, view, a, b, train, thr, data, cov))
    table = pd.DataFrame(rows)
    table.to_csv(snakemake.output.table, index=False, float_format="%.6g")
    write_claims(snakemake.output.claims, [fig4_9_claim(table, d["level"], d["coverage_threshold"])])

    fig, axes = plt.subplots(len(CASES), len(VIEWS), figsize=(4.2 * len(VIEWS), 3.6 * len(CASES)), squeeze=False)
    for n, (prim, sem, view, a, b, train, thr, data, cov) in enumerate(panels):
        ax = axes[n // len(VIEWS), n % len(VIEWS)]
        dens = data["density"].T
        (x0, x1), (y0, y1) = data["bounds"]
        ax.imshow(dens, origin="lower", extent=(x0, x1, y0, y1), cmap="viridis", aspect="equal",
                  interpolation="bilinear")
        ax.contour(data["x"], data["y"], dens, levels=[thr], colors="white", linewidths=1.2)
        ax.scatter(train[:, a], train[:, b], s=6, c="red", edgecolors="none", label="training clips")
        ax.set_xlabel(f"{AXIS[a]} (cm)", fontsize=8)
        ax.set_ylabel(f"{AXIS[b]} (cm)", fontsize=8)
        ax.tick_params(labelsize=7)
        ax.set_title(f"{prim}, {sem}, {view}\ncoverage {cov:.2f}", fontsize=9)
        if n == 0:
            ax.legend(fontsize=7, loc="upper right")
    fig.suptitle(f"Last-frame end effectors: density of {d['n_samples']} sampled motions (colour, white line: "
                 f"{d['level']:.0%} region) and training clips (red)", fontsize=10)
    fig.tight_layout()
    save(fig, snakemake.output.figure)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
