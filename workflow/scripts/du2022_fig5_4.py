"""Rule du2022_fig5_4 (Du 2022 Sec. 5.4.2-5.4.3, Fig. 5.4-5.5): random samples of the
neutral VAEs and of the stylistic CVAEs as stick figures (the last frame of each sample,
characters started side by side in a line) and as GIF animations."""


def main(snakemake) -> None:
    import logging

    import matplotlib.pyplot as plt
    import numpy as np
    import pandas as pd

    from motionvar.claims import write_claims
    from motionvar.plots import render_frames, write_gif
    from motionvar.du2022.style import diversity, features_to_positions, load_vae, sample_features
    from motionvar.du2022.style.data import example_features, primitive_mask
    from motionvar.du2022.style.figures import samples_figure
    from _style import load_inputs

    cfg, dataset, layout, space = load_inputs(snakemake)

    n = cfg["figure_samples"]
    meta = dataset.metadata

    def clip_fps(primitive):
        """Frame rate that gives the canonical clip the mean duration of its primitive."""
        rows = meta[primitive_mask(meta, primitive)]
        return (cfg["canonical_frames"] - 1) / float(((rows["n_frames"] - 1) / rows["fps"]).mean())

    fig_rows, table, gifs = [], [], {"neutral": [], "styles": []}
    for k, f in enumerate([*snakemake.input.vaes, *snakemake.input.cvaes]):
        vae, shape, info = load_vae(f)
        feats = sample_features(vae, shape, space, n, cfg["seed"] + k)
        pos = features_to_positions(feats, layout)
        example = None
        label = f"{info['primitive']}: neutral VAE"
        if info["style"] != "neutral":
            example = features_to_positions(example_features(dataset, layout, info["example"], cfg["canonical_frames"]), layout)
            example = example + np.array([0.0, 0.0, -75.0])  # left of the first sample
            label = f"{info['primitive']}: {info['style']} CVAE (grey: example {info['example']})"
        fig_rows.append((label, pos, example))
        steps = np.linalg.norm(feats[:, :-1, 3 * layout.n_joints: 3 * layout.n_joints + 2], axis=-1).sum(axis=1)
        table.append({"primitive": info["primitive"], "model": info["style"], "samples": n,
                      "step_length_mean_cm": steps.mean(), "step_length_sd_cm": steps.std(ddof=1),
                      **diversity(feats, layout.n_joints)})
        gifs["neutral" if info["style"] == "neutral" else "styles"].append(
            (pos[0], clip_fps(info["primitive"]), info["primitive"] if info["style"] == "neutral" else info["style"]))
    pd.DataFrame(table).round(4).to_csv(snakemake.output.table, index=False)
    fig = samples_figure(fig_rows, layout.parents, layout.names)
    fig.savefig(snakemake.output.figure, dpi=110)
    plt.close(fig)
    for key, out in (("neutral", snakemake.output.gif_neutral), ("styles", snakemake.output.gif_styles)):
        clips = gifs[key]
        if not clips:
            raise ValueError(f"du2022_fig5_4: no {key} models to animate")
        # each sample loops three times, so that a half-second step can be watched
        pos = [np.concatenate([p + np.array([i * (p[-1, 0, 0] - p[0, 0, 0]), 0, 0]) for i in range(3)]) for p, _, _ in clips]
        frames = render_frames(pos, [layout.parents] * len(clips), [f for _, f, _ in clips],
                               names=[layout.names] * len(clips), labels=[l for _, _, l in clips],
                               panel_px=cfg["gif_panel_px"])
        write_gif(out, frames, fps=20.0)
        logging.info("%s: %d panels, %d frames", out, len(clips), len(frames))
    write_claims(snakemake.output.claims, [])


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
