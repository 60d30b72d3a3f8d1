# Du 2022 ch. 5: convolutional motion autoencoder, a VAE per motion primitive and a CVAE per
# style with the Gram-matrix style loss (config.style). Models go to
# results/{dataset}/models/du2022_style/; evaluations: Table 5.1, Tables 5.2-5.3, Fig. 5.4-5.5.



include: "du2022_style_helpers.smk"


register_evaluation("du2022_table5_1", paper="du2022")
register_evaluation(
    "du2022_table5_2", paper="du2022", extra=["results/{dataset}/figures/du2022_style_training.png"]
)
register_evaluation(
    "du2022_fig5_4",
    paper="du2022",
    extra=[
        "results/{dataset}/figures/du2022_fig5_4_neutral.gif",
        "results/{dataset}/figures/du2022_fig5_4_styles.gif",
    ],
)


rule style_autoencoder:
    input:
        clips=f"{DATA}/clips.npz",
        metadata=f"{DATA}/metadata.csv",
        joint_map=joint_map_input,
    output:
        model=f"{STYLE_MODELS}/autoencoder.pt",
        history=f"{STYLE_MODELS}/autoencoder_history.csv",
    params:
        cfg=style_params(["seed", "canonical_frames", "autoencoder"]),
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("style_autoencoder"),
    benchmark:
        ev_benchmark("style_autoencoder")
    threads: 2
    resources:
        mem_mb=4000,
    conda:
        ENV
    script:
        "../scripts/style_autoencoder.py"


rule style_vae:
    input:
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
        autoencoder=f"{STYLE_MODELS}/autoencoder.pt",
        joint_map=joint_map_input,
    wildcard_constraints:
        primitive=STYLE_PRIMITIVE_PATTERN,
    output:
        model=f"{STYLE_MODELS}/vae/{{primitive}}.pt",
        history=f"{STYLE_MODELS}/vae/{{primitive}}_history.csv",
    params:
        cfg=style_params(["seed", "canonical_frames", "vae"]),
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("style_vae", "{primitive}"),
    benchmark:
        ev_benchmark("style_vae", "{primitive}")
    threads: 2
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/style_vae.py"


rule style_cvae:
    input:
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
        autoencoder=f"{STYLE_MODELS}/autoencoder.pt",
        vae=f"{STYLE_MODELS}/vae/{{primitive}}.pt",
        joint_map=joint_map_input,
    wildcard_constraints:
        primitive=STYLE_PRIMITIVE_PATTERN,
        style=STYLE_STYLE_PATTERN,
    output:
        model=f"{STYLE_MODELS}/cvae/{{primitive}}/{{style}}.pt",
        history=f"{STYLE_MODELS}/cvae/{{primitive}}/{{style}}_history.csv",
    params:
        cfg=style_params(["seed", "canonical_frames", "vae", "cvae"]),
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("style_cvae", "{primitive}_{style}"),
    benchmark:
        ev_benchmark("style_cvae", "{primitive}_{style}")
    threads: 2
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/style_cvae.py"


rule du2022_table5_1:
    input:
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
        autoencoder=f"{STYLE_MODELS}/autoencoder.pt",
        vae=style_vaes([STYLE_CFG["distance_primitive"]])[0],
        cvaes=style_cvaes([STYLE_CFG["distance_primitive"]]),
        joint_map=joint_map_input,
    output:
        table=in_report(ev_table("du2022_table5_1"), "du2022", "../report/du2022_table5_1.rst", table="Table 5.1"),
        figure=in_report(ev_figure("du2022_table5_1"), "du2022", "../report/du2022_table5_1.rst", figure="Table 5.1"),
        claims=ev_claims("du2022_table5_1"),
    params:
        cfg=style_params(["seed", "canonical_frames", "distance_primitive", "distance_samples"]),
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("du2022_table5_1"),
    benchmark:
        ev_benchmark("du2022_table5_1")
    threads: 2
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/du2022_table5_1.py"


rule du2022_table5_2:
    input:
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
        autoencoder=f"{STYLE_MODELS}/autoencoder.pt",
        vaes=style_vaes(STYLE_CFG["style_primitives"]),
        cvaes=style_cvaes(STYLE_CFG["style_primitives"]),
        joint_map=joint_map_input,
    output:
        table=in_report(ev_table("du2022_table5_2"), "du2022", "../report/du2022_table5_2.rst", table="Tables 5.2-5.3"),
        figure=in_report(ev_figure("du2022_table5_2"), "du2022", "../report/du2022_table5_2.rst", figure="Tables 5.2-5.3"),
        claims=ev_claims("du2022_table5_2"),
    params:
        cfg=style_params(["seed", "canonical_frames", "style_primitives", "diversity_samples", "pose_sd_tolerance"]),
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("du2022_table5_2"),
    benchmark:
        ev_benchmark("du2022_table5_2")
    threads: 2
    resources:
        mem_mb=6000,
    conda:
        ENV
    script:
        "../scripts/du2022_table5_2.py"


rule du2022_fig5_4:
    input:
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
        autoencoder=f"{STYLE_MODELS}/autoencoder.pt",
        vaes=style_vaes(STYLE_CFG["vae_primitives"]),
        cvaes=style_cvaes([STYLE_CFG["distance_primitive"]]),
        joint_map=joint_map_input,
    output:
        table=in_report(ev_table("du2022_fig5_4"), "du2022", "../report/du2022_fig5_4.rst", table="Fig. 5.4-5.5"),
        figure=in_report(ev_figure("du2022_fig5_4"), "du2022", "../report/du2022_fig5_4.rst", figure="Fig. 5.4-5.5"),
        claims=ev_claims("du2022_fig5_4"),
        gif_neutral=in_report(
            "results/{dataset}/figures/du2022_fig5_4_neutral.gif", "du2022", "../report/du2022_fig5_4.rst",
            figure="Fig. 5.4 animation",
        ),
        gif_styles=in_report(
            "results/{dataset}/figures/du2022_fig5_4_styles.gif", "du2022", "../report/du2022_fig5_4.rst",
            figure="Fig. 5.5 animation",
        ),
    params:
        cfg=style_params(["seed", "canonical_frames", "figure_samples", "gif_panel_px"]),
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("du2022_fig5_4"),
    benchmark:
        ev_benchmark("du2022_fig5_4")
    threads: 2
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/du2022_fig5_4.py"


rule style_training_curves:
    input:
        autoencoder=f"{STYLE_MODELS}/autoencoder_history.csv",
        vaes=style_vaes(STYLE_CFG["vae_primitives"], "history"),
        cvaes=style_cvaes(STYLE_CFG["style_primitives"], "history"),
    output:
        figure=in_report(
            "results/{dataset}/figures/du2022_style_training.png", "du2022", "../report/du2022_style_training.rst",
            figure="training curves (ch. 5)",
        ),
    log:
        ev_log("style_training_curves"),
    benchmark:
        ev_benchmark("style_training_curves")
    threads: 1
    resources:
        mem_mb=1000,
    conda:
        ENV
    script:
        "../scripts/style_training_curves.py"
