"""Rule egges2004_model (Egges 2004 Sec. 3.2, 5.1-5.3, 5.6, 6): posture PCA of the idle
clips' training part, one idle database per subject, the resting-posture categories
checked against the ground truth, and the category transition graphs (Fig. 3)."""


def main(snakemake) -> None:
    import logging
    from pathlib import Path

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from _egges2004 import figure_subjects, joint_map, save
    from motionvar.egges2004 import IdleSettings
    from motionvar.egges2004.figures import plot_category_graph
    from motionvar.egges2004.pipeline import category_check, fit_idle_model, idle_clips, save_model, split_clips
    from motionvar.io import load_dataset

    o = snakemake.params.options
    folder = Path(snakemake.input.clips).parent
    clips = idle_clips(load_dataset(folder), str(folder))
    train, test = split_clips(clips, o["held_out_clips"])
    model, _ = fit_idle_model(
        train, test, joint_map(snakemake), IdleSettings(**o["analysis"]), o["translation_scale"], o["seed"]
    )
    save_model(snakemake.output.model, model)
    check = category_check(model, train)
    check.to_csv(snakemake.output.categories, index=False)
    shown = figure_subjects(model, o)
    fig, axes = plt.subplots(1, len(shown), figsize=(4.2 * len(shown), 4.4), squeeze=False)
    for ax, s in zip(axes[0], shown):
        plot_category_graph(ax, model.databases[s].graph, f"subject {s}")
    fig.suptitle("Category transition graphs: P(c1 => c2) on the arrows, T_min - T_max in the nodes (Fig. 3)",
                 fontsize=10)
    fig.tight_layout()
    save(fig, snakemake.output.graph)
    logging.info("%d subjects, %d training clips; categories:\n%s", len(model.databases),
                 sum(map(len, model.train_clips.values())), check.to_string())


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
