"""Rule egges2004_model (Egges 2004 Sec. 3.2, 5.1-5.3, 5.6, 6): posture PCA of the idle
clips' training part and one idle database per subject (saved as .npz + .json), the
resting-posture categories checked against the ground truth, and the category transition
graphs (Fig. 3)."""


def main(snakemake) -> None:
    import logging

    from _egges2004 import prep, save_figure, settings
    from _rule import joint_map

    from motionvar.egges2004.evaluations import category_check
    from motionvar.egges2004.figures import draw_categories
    from motionvar.egges2004.pipeline import fit_idle_model, idle_clips, split_idle
    from motionvar.egges2004.storage import save_idle_model

    s = settings(snakemake)
    train, test = split_idle(idle_clips(*prep(snakemake)), s)
    model, _ = fit_idle_model(train, test, joint_map(snakemake), s)
    save_idle_model(snakemake.output.model, model)
    result = category_check(model, train, s)
    result.table.to_csv(snakemake.output.categories, index=False)
    save_figure(draw_categories(result), snakemake.output.graph)
    logging.info("%d subjects; categories:\n%s", len(model.databases), result.table.to_string())
    logging.info(
        "posture PCA (Sec. 3.2): %d dimensions; %s of the variance in the first %s PCs (the paper gives no share)",
        len(model.pca.explained_variance_),
        " / ".join(f"{q:.0%}" for q in (0.9, 0.95, 0.99)),
        " / ".join(str(model.pca.components_for(q)) for q in (0.9, 0.95, 0.99)),
    )


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
