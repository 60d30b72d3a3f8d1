"""Rule du2022_table5_2 (Du 2022 Sec. 5.4.5, Tables 5.2-5.3): pose_SD, V_SD and step_SD
(Eq. 5.13-5.15) of the training data, the neutral VAE and the six CVAEs, for walk left
and right stance."""


def main(snakemake) -> None:
    import logging

    import matplotlib.pyplot as plt
    import pandas as pd

    from motionvar.claims import Claim, verdict_from_fraction, write_claims
    from motionvar.du2022.style import active_units, diversity, load_vae, sample_features
    from motionvar.du2022.style.data import primitive_features
    from motionvar.du2022.style.figures import diversity_figure
    from motionvar.du2022.style.published import diversity_tables
    from _style import load_inputs

    cfg, dataset, layout, space = load_inputs(snakemake)

    n = cfg["diversity_samples"]
    J = layout.n_joints
    rows = []
    models = [load_vae(f) for f in [*snakemake.input.vaes, *snakemake.input.cvaes]]
    for k, primitive in enumerate(cfg["style_primitives"]):
        _, train = primitive_features(dataset, layout, primitive, "neutral", cfg["canonical_frames"])
        rows.append({"primitive": primitive, "model": "training data", "n": len(train), **diversity(train, J)})
        train_maps = space.encode(train)
        for j, (vae, shape, info) in enumerate(m for m in models if m[2]["primitive"] == primitive):
            feats = sample_features(vae, shape, space, n, cfg["seed"] + 1000 * k + j)
            rows.append({"primitive": primitive, "model": info["style"], "n": n, **diversity(feats, J),
                         "active_latents": active_units(vae, train_maps)})
    table = pd.DataFrame(rows)
    pub = diversity_tables().rename(columns={c: f"published_{c}" for c in ("pose_sd", "v_sd", "step_sd")})
    table = table.merge(pub, on=["primitive", "model"], how="left")
    table.round(5).to_csv(snakemake.output.table, index=False)
    logging.info("diversity:\n%s", table.round(4).to_string())

    fig = diversity_figure(table)
    fig.savefig(snakemake.output.figure, dpi=120)
    plt.close(fig)

    t = table.set_index(["primitive", "model"])
    prims = cfg["style_primitives"]
    tol = cfg["pose_sd_tolerance"]
    rel = {p: abs(t.loc[(p, "neutral"), "pose_sd"] / t.loc[(p, "training data"), "pose_sd"] - 1) for p in prims}
    step = {p: (t.loc[(p, "neutral"), "step_sd"], t.loc[(p, "training data"), "step_sd"]) for p in prims}
    styles = [m for m in t.index.get_level_values("model").unique() if m not in ("training data", "neutral")]
    lower = [(p, s) for p in prims for s in styles if t.loc[(p, s), "pose_sd"] < t.loc[(p, "neutral"), "pose_sd"]]
    neutral_active = ", ".join(f"{p}: {int(t.loc[(p, 'neutral'), 'active_latents'])}" for p in prims)
    note = (f"{n} samples a model; synthetic data, CMU 21-joint subset, reduced training budgets (see the caption); "
            f"latent dimensions in use by the neutral VAE (of {models[0][0].latent}): {neutral_active}.")
    write_claims(snakemake.output.claims, [
        Claim(
            claim_id="du2022.table5_2.neutral_pose_sd_close_to_training", paper="du2022", source="Tables 5.2-5.3",
            statement=f"The neutral VAE's pose_SD is close to the training data's (within {tol:.0%}).",
            published="52.68 vs 52.86 (left), 52.88 vs 53.04 (right): within 0.4%",
            measured="; ".join(f"{p}: {t.loc[(p, 'neutral'), 'pose_sd']:.2f} vs "
                               f"{t.loc[(p, 'training data'), 'pose_sd']:.2f} ({rel[p]:.1%})" for p in prims),
            verdict=verdict_from_fraction(sum(r <= tol for r in rel.values()), len(prims)), note=note,
        ),
        Claim(
            claim_id="du2022.table5_2.neutral_step_sd_lower_than_training", paper="du2022", source="Tables 5.2-5.3",
            statement="The neutral VAE's step-length SD is lower than the training data's.",
            published="7.66 < 10.12 (left), 7.51 < 9.98 (right)",
            measured="; ".join(f"{p}: {a:.2f} vs {b:.2f}" for p, (a, b) in step.items()),
            verdict=verdict_from_fraction(sum(a < b for a, b in step.values()), len(prims)), note=note,
        ),
        Claim(
            claim_id="du2022.table5_2.style_pose_sd_lower_than_neutral", paper="du2022", source="Tables 5.2-5.3",
            statement="Every stylistic model's pose_SD is lower than the neutral VAE's.",
            published="12 of 12 (6 styles x 2 primitives)",
            measured=f"{len(lower)} of {len(prims) * len(styles)}",
            verdict=verdict_from_fraction(len(lower), len(prims) * len(styles)), note=note,
        ),
    ])


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
