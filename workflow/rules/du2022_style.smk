# Du 2022 ch. 5: convolutional motion autoencoder, a VAE per motion primitive and a CVAE per
# style with the Gram-matrix style loss (config.style). Models go to
# results/{dataset}/models/du2022_style/ (<name>.pt state dict + <name>.json settings);
# evaluations: Table 5.1, Tables 5.2-5.3, Fig. 5.4-5.5 (motionvar.du2022.style.evaluations).


include: "du2022_style_helpers.smk"


rule style_autoencoder:
    input:
        clips=f"{DATA}/clips.npz",
        metadata=f"{DATA}/metadata.csv",
        joint_map=joint_map_input,
    output:
        model=f"{STYLE_MODELS}/autoencoder.pt",
        settings=f"{STYLE_MODELS}/autoencoder.json",
        history=f"{STYLE_MODELS}/autoencoder_history.csv",
    params:
        options=config_params("style", ["seed", "canonical_frames", "autoencoder"]),
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("style_autoencoder"),
    benchmark:
        ev_benchmark("style_autoencoder")
    priority: PRIORITY["style_autoencoder"]
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
        autoencoder_settings=f"{STYLE_MODELS}/autoencoder.json",
        joint_map=joint_map_input,
    wildcard_constraints:
        primitive=STYLE_PRIMITIVE_PATTERN,
    output:
        model=f"{STYLE_MODELS}/vae/{{primitive}}.pt",
        settings=f"{STYLE_MODELS}/vae/{{primitive}}.json",
        history=f"{STYLE_MODELS}/vae/{{primitive}}_history.csv",
    params:
        options=config_params("style", ["seed", "canonical_frames", "vae"]),
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("style_vae", "{primitive}"),
    benchmark:
        ev_benchmark("style_vae", "{primitive}")
    priority: PRIORITY["style_vae"]
    # one thread: the same weights bit for bit as with two (measured), and two such jobs side by
    # side take ~20 % less CPU than one on two threads (OpenMP's waiting threads)
    threads: 1
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
        autoencoder_settings=f"{STYLE_MODELS}/autoencoder.json",
        vae=f"{STYLE_MODELS}/vae/{{primitive}}.pt",
        vae_settings=f"{STYLE_MODELS}/vae/{{primitive}}.json",
        joint_map=joint_map_input,
    wildcard_constraints:
        primitive=STYLE_PRIMITIVE_PATTERN,
        style=STYLE_STYLE_PATTERN,
    output:
        model=f"{STYLE_MODELS}/cvae/{{primitive}}/{{style}}.pt",
        settings=f"{STYLE_MODELS}/cvae/{{primitive}}/{{style}}.json",
        history=f"{STYLE_MODELS}/cvae/{{primitive}}/{{style}}_history.csv",
    params:
        options=config_params(
            "style", ["seed", "canonical_frames", "vae.samples_per_input", "vae.latent", "cvae"]
        ),
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("style_cvae", "{primitive}_{style}"),
    benchmark:
        ev_benchmark("style_cvae", "{primitive}_{style}")
    priority: PRIORITY["style_cvae"]
    # one thread: the same weights bit for bit as with two (measured), and two such jobs side by
    # side take ~20 % less CPU than one on two threads (OpenMP's waiting threads)
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/style_cvae.py"


# the rig's mean skeleton, feature layout and frame rates, for decoding the style models
# into joint rotations with `motionvar du2022 style` (in the default target: DATASET_MODELS)
rule style_rig:
    input:
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
        joint_map=joint_map_input,
    output:
        model=STYLE_RIG[0],
        settings=STYLE_RIG[1],
    params:
        options=config_params("style", ["canonical_frames"]),
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("style_rig"),
    benchmark:
        ev_benchmark("style_rig")
    threads: 1
    resources:
        mem_mb=2000,
    conda:
        ENV
    script:
        "../scripts/style_rig.py"


# The evaluations share one rule body: the prepared clips, the autoencoder, the neutral
# VAEs of `vaes` and the CVAEs of `cvaes` (primitives) in; table, figure, claims (and
# GIFs) out; params: the config.style keys listed. The script, workflow/scripts/<evaluation>.py,
# is named through params (a script: line is evaluated when the job runs, after the loop).
_DISTANCE_PRIMITIVE = [STYLE_CFG["distance_primitive"]]
STYLE_EVALUATIONS = {
    "du2022_table5_1": dict(
        label="Table 5.1",
        vaes=_DISTANCE_PRIMITIVE,
        cvaes=_DISTANCE_PRIMITIVE,
        keys=["seed", "canonical_frames", "distance_primitive", "distance_samples"],
        mem_mb=3000,
        extra=[],
        gifs={},
    ),
    "du2022_table5_2": dict(
        label="Tables 5.2-5.3",
        vaes=STYLE_CFG["style_primitives"],
        cvaes=STYLE_CFG["style_primitives"],
        keys=["seed", "canonical_frames", "style_primitives", "diversity_samples", "pose_sd_tolerance"],
        mem_mb=6000,
        extra=["results/{dataset}/figures/du2022_style_training.png"],
        gifs={},
    ),
    "du2022_fig5_4": dict(
        label="Fig. 5.4-5.5",
        vaes=STYLE_CFG["vae_primitives"],
        cvaes=_DISTANCE_PRIMITIVE,
        keys=["seed", "canonical_frames", "figure_samples", "gif_panel_px"],
        mem_mb=3000,
        extra=[],
        gifs={"gif_neutral": "Fig. 5.4 animation", "gif_styles": "Fig. 5.5 animation"},
    ),
}

for _style_ev, _style_spec in STYLE_EVALUATIONS.items():
    _style_caption = f"../report/{_style_ev}.rst"
    _style_gifs = {  # output gif_<what> -> results/{dataset}/figures/<evaluation>_<what>.gif
        _style_key: f"results/{{dataset}}/figures/{_style_ev}_{_style_key.removeprefix('gif_')}.gif"
        for _style_key in _style_spec["gifs"]
    }
    register_evaluation(_style_ev, paper="du2022", extra=_style_spec["extra"] + list(_style_gifs.values()))

    rule:
        name:
            _style_ev
        input:
            clips=f"{PREP}/clips.npz",
            metadata=f"{PREP}/metadata.csv",
            autoencoder=f"{STYLE_MODELS}/autoencoder.pt",
            autoencoder_settings=f"{STYLE_MODELS}/autoencoder.json",
            vaes=style_vaes(_style_spec["vaes"]),
            vae_settings=style_vaes(_style_spec["vaes"], "settings"),
            cvaes=style_cvaes(_style_spec["cvaes"]),
            cvae_settings=style_cvaes(_style_spec["cvaes"], "settings"),
            joint_map=joint_map_input,
        output:
            table=in_report(ev_table(_style_ev), "du2022", _style_caption, table=_style_spec["label"]),
            figure=in_report(ev_figure(_style_ev), "du2022", _style_caption, figure=_style_spec["label"]),
            claims=ev_claims(_style_ev),
            **{
                _style_key: in_report(_style_gif, "du2022", _style_caption, figure=_style_spec["gifs"][_style_key])
                for _style_key, _style_gif in _style_gifs.items()
            },
        params:
            evaluation=_style_ev,
            options=config_params("style", _style_spec["keys"]),
            joint_map=lambda wc: joint_map_path(wc.dataset),
        log:
            ev_log(_style_ev),
        benchmark:
            ev_benchmark(_style_ev)
        # one thread: the same tables and claims as on two (measured at CI and full size), and a
        # one-core job need not wait until no other job holds a core
        threads: 1
        resources:
            mem_mb=_style_spec["mem_mb"],
        conda:
            ENV
        script:
            "../scripts/{params.evaluation}.py"


rule style_training_curves:
    input:
        autoencoder=f"{STYLE_MODELS}/autoencoder_history.csv",
        vaes=style_vaes(STYLE_CFG["vae_primitives"], "history"),
        cvaes=style_cvaes(STYLE_CFG["style_primitives"], "history"),
    output:
        figure=in_report(
            "results/{dataset}/figures/du2022_style_training.png",
            "du2022",
            "../report/du2022_style_training.rst",
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
