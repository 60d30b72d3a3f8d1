"""Rule du2022_table5_1 (Du 2022 Sec. 5.4.3, Table 5.1): style distance D(m, s) (Eq. 5.12)
between the samples of each model (neutral VAE, six CVAEs) and each style example."""


def main(snakemake) -> None:
    import logging

    import matplotlib.pyplot as plt

    from motionvar.claims import Claim, verdict_from_fraction, write_claims
    from motionvar.du2022.style import diagonal_minima, load_vae, style_distance_matrix
    from motionvar.du2022.style.data import example_features, primitive_features
    from motionvar.du2022.style.figures import distance_heatmap
    from motionvar.du2022.style.published import table5_1
    from _style import load_inputs

    cfg, dataset, layout, space = load_inputs(snakemake)

    primitive = cfg["distance_primitive"]
    vae, shape, _ = load_vae(snakemake.input.vae)
    models, examples = {"neutral": (vae, shape)}, {}
    # "For neutral, we use the mean motion as the style example"
    _, neutral = primitive_features(dataset, layout, primitive, "neutral", cfg["canonical_frames"])
    examples["neutral"] = neutral.mean(axis=0)
    example_ids = {"neutral": "mean of the neutral clips"}
    for f in snakemake.input.cvaes:
        cvae, shape, info = load_vae(f)
        models[info["style"]] = (cvae, shape)
        examples[info["style"]] = example_features(dataset, layout, info["example"], cfg["canonical_frames"])
        example_ids[info["style"]] = info["example"]
    n = cfg["distance_samples"]
    table = style_distance_matrix(models, examples, space, n, cfg["seed"])
    published = table5_1()
    on_diag = diagonal_minima(table)
    out = table.copy()
    out.insert(0, "style_example_clip", [example_ids[m] for m in table.index])
    out["row_minimum_at"] = table.idxmin(axis=1)
    out["published_row_minimum_at"] = published.loc[table.index, table.columns].idxmin(axis=1)
    out.round(6).to_csv(snakemake.output.table)
    logging.info("style distances (%d samples a model):\n%s", n, table.round(4).to_string())

    fig = distance_heatmap(table, published)
    fig.savefig(snakemake.output.figure, dpi=130)
    plt.close(fig)

    rows = len(table)
    off = [f"{r}->{table.loc[r].idxmin()}" for r in table.index if r not in on_diag]
    write_claims(snakemake.output.claims, [Claim(
        claim_id="du2022.table5_1.diagonal_dominant", paper="du2022", source="Table 5.1",
        statement="Samples of each stylistic model (and the neutral VAE) are closer, in Gram-matrix style "
                  "distance (Eq. 5.12), to their own style example than to any other style's example.",
        published="7 of 7 rows have their minimum on the diagonal",
        measured=f"{len(on_diag)} of {rows} rows have their minimum on the diagonal"
                 + (f" (off: {', '.join(off)})" if off else ""),
        verdict=verdict_from_fraction(len(on_diag), rows),
        note=f"{primitive}, {n} samples a model; training budgets are a fraction of the thesis' "
             "(see the caption); synthetic styles, CMU 21-joint subset.",
    )])


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
