"""Rule du2022_fig4_10 (Du 2022 Fig. 4.10): constrained motion generation with the
Morphable Graph: a walk following a floor path (graph walk, Algorithm 1) and reaching
targets with the picking primitive; each step seeded by the k-means tree and optimised
by Levenberg-Marquardt on Eq. 4.9. The table lists the constraint errors that remain."""

REACH_JOINT = "right_hand"
PATH_CLOSE_CM = 10.0  # "follows the path": mean remaining hips position error per step
REACH_CLOSE_CM = 2.0  # "reaches the target": remaining hand distance


def main(snakemake) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    import pandas as pd

    from _graph import joint_map, load_model, save, semantic_index
    from motionvar.claims import Claim, verdict_from_fraction, verdict_threshold
    from motionvar.du2022.graph import (
        Constraint, MorphableGraph, Path2D, SpacePartitioningTree, WalkSettings, concatenate_steps, follow_path,
        synthesize_step,
    )
    from motionvar.plots import animate_motions, draw_pose, project

    o = snakemake.params.options
    sy = o["synthesis"]
    jm = joint_map(snakemake)
    models = {}
    for p in snakemake.input.models:
        if p.endswith(".npz"):
            m = load_model(p)
            models[m.name] = m
    rng = np.random.default_rng([o["seed"], 410])
    trees = {n: SpacePartitioningTree(m.sample(sy["tree_samples"], rng), "kmeans", seed=o["seed"])
             for n, m in models.items()}
    meta = pd.read_csv(snakemake.input.metadata)
    walk_names = [n for n in models if n.startswith("walk_")]
    graph = MorphableGraph.from_metadata(meta, {n: models[n] for n in walk_names})
    path = Path2D(np.asarray(sy["path"], dtype=float))
    settings = WalkSettings(max_steps=sy["max_steps"], beam=sy["beam"], likelihood_weight=sy["likelihood_weight"],
                            method=sy["method"], max_nfev=sy["max_nfev"])
    steps = follow_path(graph, trees, path, jm, settings)
    rows = []
    for i, st in enumerate(steps):
        rows.append(dict(task="path", item=i, primitive=st.primitive, position_error_tree_cm=st.fit.errors_before[0],
                         position_error_cm=st.fit.errors_after[0], heading_error_tree_deg=st.fit.errors_before[1],
                         heading_error_deg=st.fit.errors_after[1], tree_evaluations=st.tree_evals,
                         log_prob=st.fit.log_prob_after))
    walk = concatenate_steps(steps)
    hips = jm.index(walk.skeleton, "hips")
    end_gap = float(np.linalg.norm(walk.positions()[-1, hips, [0, 2]] - path.points[-1]))

    name = sy["reach_primitive"]
    reach = models[name]
    hand = semantic_index(jm, reach.skeleton, REACH_JOINT, "graph.synthesis (reach joint)")
    from _graph import primitive_clips

    clips, _ = primitive_clips(snakemake.input.clips, name)
    picks = rng.choice(len(clips), size=min(sy["reach_targets"], len(clips)), replace=False)
    reaches, targets = [], []
    for k, c in enumerate(picks):
        direction = rng.normal(size=3)
        target = clips[c].positions()[-1, hand] + sy["reach_offset_cm"] * direction / np.linalg.norm(direction)
        cons = [Constraint("position", reach.n_frames - 1, (hand,), target[None])]
        fit, tree_err, evals = synthesize_step(reach, trees[name], cons, sy["beam"], sy["likelihood_weight"],
                                               sy["method"], sy["max_nfev"])
        motion = reach.to_motions(fit.latent[None])[0]
        reaches.append(motion)
        targets.append(target)
        rows.append(dict(task="reach", item=k, primitive=name, position_error_tree_cm=tree_err,
                         position_error_cm=fit.errors_after[0], tree_evaluations=evals, log_prob=fit.log_prob_after))
    table = pd.DataFrame(rows)
    table.to_csv(snakemake.output.table, index=False, float_format="%.6g")

    path_rows = table[table["task"] == "path"]
    reach_rows = table[table["task"] == "reach"]
    mean_step = float(path_rows["position_error_cm"].mean())
    ok = int((reach_rows["position_error_cm"] <= REACH_CLOSE_CM).sum())
    claims = [
        Claim("du2022.fig4_10.follows_path", "du2022", "Fig. 4.10 (left)",
              "A graph walk of walking primitives follows a floor path.",
              "path following (qualitative figure)",
              f"{len(steps)} steps; hips position error per step after LM {mean_step:.1f} cm (tree: "
              f"{path_rows['position_error_tree_cm'].mean():.1f} cm), heading {path_rows['heading_error_deg'].mean():.1f}"
              f" deg; end of walk {end_gap:.0f} cm from the path's end",
              verdict_threshold(mean_step, PATH_CLOSE_CM, "<=", tolerance=1.0),
              note=f"reproduced when the mean remaining step position error is <= {PATH_CLOSE_CM:.0f} cm (partial up "
                   "to twice that); steps are not blended and all steps are not optimised together (Algorithm 1, "
                   "line 9 left out)."),
        Claim("du2022.fig4_10.reaches_targets", "du2022", "Fig. 4.10 (right)",
              "Targets within the variation range are reached by the picking primitive.",
              "reaching targets (qualitative figure)",
              f"{ok} of {len(reach_rows)} targets within {REACH_CLOSE_CM:.0f} cm; errors after LM "
              + ", ".join(f"{e:.2f}" for e in reach_rows["position_error_cm"]) + " cm (tree: "
              + ", ".join(f"{e:.1f}" for e in reach_rows["position_error_tree_cm"]) + " cm)",
              verdict_from_fraction(ok, len(reach_rows)),
              note=f"targets: training end positions of the {REACH_JOINT} moved {sy['reach_offset_cm']:g} cm in a random "
                   f"direction; reproduced when every remaining error is <= {REACH_CLOSE_CM:.0f} cm."),
    ]
    from motionvar.claims import write_claims

    write_claims(snakemake.output.claims, claims)

    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(12, 5), gridspec_kw=dict(width_ratios=[1.1, 1]))
    pos = walk.positions()
    ax0.plot(path.points[:, 0], path.points[:, 1], color="0.6", linewidth=6, alpha=0.5, label="path constraint")
    ax0.plot(pos[:, hips, 0], pos[:, hips, 2], color="tab:blue", linewidth=1.5, label="hips of the generated walk")
    for foot, colour in (("left_ankle", "tab:cyan"), ("right_ankle", "tab:red")):
        f = jm.index(walk.skeleton, foot)
        ax0.plot(pos[::4, f, 0], pos[::4, f, 2], ".", color=colour, markersize=2, label=foot.replace("_", " "))
    for st in steps:
        e = st.motion.positions()[-1, hips]
        ax0.plot(e[0], e[2], "k|", markersize=8)
    ax0.set_aspect("equal")
    ax0.set_xlabel("x (cm)")
    ax0.set_ylabel("z (cm)")
    ax0.set_title(f"Path following: {len(steps)} primitives ({', '.join(s.primitive.replace('walk_', '') for s in steps[:3])}, ...)",
                  fontsize=9)
    ax0.legend(fontsize=7, loc="best")
    spacing = 90.0
    for k, (m, t) in enumerate(zip(reaches, targets)):
        p = m.positions()
        xy = project(p[-1], (1.0, 0.0, 0.0), azimuth_deg=30.0)  # from the side, turned to part the arms
        txy = project(t, (1.0, 0.0, 0.0), azimuth_deg=30.0)
        shift = k * spacing - xy[0, 0]
        xy[:, 0] += shift
        draw_pose(ax1, xy, m.skeleton.parents, m.skeleton.names)
        ax1.plot(txy[0] + shift, txy[1], "o", color="red", markersize=6)
    ax1.set_aspect("equal")
    ax1.autoscale_view()
    ax1.set_xlabel("poses side by side (cm)")
    ax1.set_ylabel("height (cm)")
    ax1.set_title(f"Reaching with {name}: last frame, right-hand targets (red)", fontsize=9)
    fig.tight_layout()
    save(fig, snakemake.output.figure)
    animate_motions(snakemake.output.gif, [walk] + reaches[:2], labels=["path following"] +
                    [f"reach {k + 1}" for k in range(min(2, len(reaches)))], max_seconds=8.0, panel_px=220)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
