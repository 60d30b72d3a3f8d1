# Du 2022 ch. 5: convolutional motion autoencoder, a VAE per motion primitive and a CVAE per
# style with the Gram-matrix style loss (config.du2022_style, motionvar.du2022.style.settings). Models
# go to results/{dataset}/models/du2022_style/ (<name>.pt state dict + <name>.json settings);
# evaluations: Table 5.1, Tables 5.2-5.3, Fig. 5.4-5.5 (motionvar.du2022.style.evaluations).
# Every rule gets the section as params.settings (section_for: less the keys one evaluation owns).


include: "du2022_style_helpers.smk"


rule du2022_style_autoencoder:
    input:
        clips=f"{DATA}/clips.npz",
        metadata=f"{DATA}/metadata.csv",
        joint_map=joint_map_input,
    output:
        model=f"{STYLE_MODELS}/autoencoder.pt",
        settings=f"{STYLE_MODELS}/autoencoder.json",
        history=f"{STYLE_MODELS}/autoencoder_history.csv",
    params:
        settings=section_for("du2022_style"),
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("du2022_style_autoencoder"),
    benchmark:
        ev_benchmark("du2022_style_autoencoder")
    priority: PRIORITY["du2022_style_autoencoder"]
    threads: 2
    resources:
        mem_mb=4000,
    conda:
        ENV
    script:
        "../scripts/du2022_style_autoencoder.py"


rule du2022_style_vae:
    input:
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
        autoencoder=f"{STYLE_MODELS}/autoencoder.pt",
        autoencoder_settings=f"{STYLE_MODELS}/autoencoder.json",
        joint_map=joint_map_input,
    wildcard_constraints:
        primitive=STYLE_PRIMITIVE_PATTERN,
    output:
        model=f"{STYLE_MODELS}/vae/{{primitive}}.pt",
        settings=f"{STYLE_MODELS}/vae/{{primitive}}.json",
        history=f"{STYLE_MODELS}/vae/{{primitive}}_history.csv",
    params:
        settings=section_for("du2022_style"),
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("du2022_style_vae", "{primitive}"),
    benchmark:
        ev_benchmark("du2022_style_vae", "{primitive}")
    priority: PRIORITY["du2022_style_vae"]
    # one thread: the same weights bit for bit as with two (measured), and two such jobs side by
    # side take ~20 % less CPU than one on two threads (OpenMP's waiting threads)
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/du2022_style_vae.py"


# every style of a primitive in one job: each CVAE is seeded alike (the same weights as one job
# per style) and the job reads the clips and imports torch once
rule du2022_style_cvae:
    input:
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
        autoencoder=f"{STYLE_MODELS}/autoencoder.pt",
        autoencoder_settings=f"{STYLE_MODELS}/autoencoder.json",
        vae=f"{STYLE_MODELS}/vae/{{primitive}}.pt",
        vae_settings=f"{STYLE_MODELS}/vae/{{primitive}}.json",
        joint_map=joint_map_input,
    wildcard_constraints:
        primitive=STYLE_PRIMITIVE_PATTERN,
    output:
        model=style_cvaes(["{primitive}"]),
        settings=style_cvaes(["{primitive}"], "settings"),
        history=style_cvaes(["{primitive}"], "history"),
    params:
        settings=section_for("du2022_style"),
        styles=STYLE_CFG["styles"],
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("du2022_style_cvae", "{primitive}"),
    benchmark:
        ev_benchmark("du2022_style_cvae", "{primitive}")
    priority: PRIORITY["du2022_style_cvae"]
    # one thread: the same weights bit for bit as with two (measured), and two such jobs side by
    # side take ~20 % less CPU than one on two threads (OpenMP's waiting threads)
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/du2022_style_cvae.py"


# the rig's mean skeleton, feature layout and frame rates, for decoding the style models
# into joint rotations with `motionvar du2022 style` (in the default target: DATASET_MODELS)
rule du2022_style_rig:
    input:
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
        joint_map=joint_map_input,
    output:
        model=STYLE_RIG[0],
        settings=STYLE_RIG[1],
    params:
        settings=section_for("du2022_style"),
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("du2022_style_rig"),
    benchmark:
        ev_benchmark("du2022_style_rig")
    threads: 1
    resources:
        mem_mb=2000,
    conda:
        ENV
    script:
        "../scripts/du2022_style_rig.py"


rule du2022_style_training_curves:
    input:
        autoencoder=f"{STYLE_MODELS}/autoencoder_history.csv",
        vaes=style_vaes(STYLE_CFG["vae_primitives"], "history"),
        cvaes=style_cvaes(STYLE_CFG["style_primitives"], "history"),
    output:
        figure=in_report(
            STYLE_TRAINING_FIGURE,
            "du2022",
            "../report/du2022_style_training.rst",
            figure="training curves (ch. 5)",
        ),
    log:
        ev_log("du2022_style_training_curves"),
    benchmark:
        ev_benchmark("du2022_style_training_curves")
    threads: 1
    resources:
        mem_mb=1000,
    conda:
        ENV
    script:
        "../scripts/du2022_style_training_curves.py"


# The input sets of the evaluations (motionvar.du2022.catalog; rules made by evaluations.smk): the
# prepared clips, the autoencoder, the neutral VAEs and the CVAEs of the primitives named
# (style_evaluation_inputs). One thread each: the same tables and claims as on two (measured at CI
# and full size), and a one-core job need not wait until no other job holds a core.
add_input_set(
    "du2022_style_distance",
    style_evaluation_inputs([STYLE_CFG["distance_primitive"]], [STYLE_CFG["distance_primitive"]]),
)
add_input_set(
    "du2022_style_diversity",
    style_evaluation_inputs(STYLE_CFG["style_primitives"], STYLE_CFG["style_primitives"]),
)
add_input_set(
    "du2022_style_samples",
    style_evaluation_inputs(STYLE_CFG["vae_primitives"], [STYLE_CFG["distance_primitive"]]),
)
add_to_evaluation("du2022_table5_2", extra=(STYLE_TRAINING_FIGURE,))
# Fig. 5.4-5.5's GIFs
add_to_evaluation(
    "du2022_fig5_4",
    outputs={
        "gif_neutral": in_report(
            "results/{dataset}/figures/du2022_fig5_4_neutral.gif",
            "du2022",
            "../report/du2022_fig5_4.rst",
            page="gif_page_du2022_fig5_4_neutral",
            figure="Fig. 5.4 animation",
        ),
        "gif_styles": in_report(
            "results/{dataset}/figures/du2022_fig5_4_styles.gif",
            "du2022",
            "../report/du2022_fig5_4.rst",
            page="gif_page_du2022_fig5_4_styles",
            figure="Fig. 5.5 animation",
        ),
    },
)
