# Egges, Molet, Magnenat-Thalmann 2004, "Personalised Real-time Idle Motion Synthesis":
# posture PCA (Sec. 3.2), one idle database per subject (Sec. 5-6), and the evaluations of
# Sec. 5.4 (fitting), 6 (repetition) and 8 (identification, real time). Options:
# config.egges2004 (config/schema.yaml). Inputs: the idle clips of results/{dataset}/prep/.
# Library: motionvar.egges2004 (the method, pipeline, storage), its evaluations/ and figures.

EGGES = "results/{dataset}/models/egges2004"
# the fitted model of all subjects: arrays and settings (motionvar.egges2004.storage)
EGGES_MODEL = {"model": f"{EGGES}/idle_model.npz", "model_settings": f"{EGGES}/idle_model.json"}
EGGES_PREP = {"clips": f"{PREP}/clips.npz", "metadata": f"{PREP}/metadata.csv", "joint_map": joint_map_input}

# evaluation -> its report label, whether it reads the prep clips (and the joint map),
# the keys of config.egges2004 it reads, memory, further outputs of the rule, and further
# outputs registered with it for the default target.
EGGES_EVALUATIONS = {
    "identification": {
        "label": "Sec. 8: person identification",
        "prep": True,
        "keys": ["seed", "identification", "perlin_frequency_hz", "analysis.support_margin"],
        "mem_mb": 4000,
        "outputs": {},
        "extra": ["results/{dataset}/figures/egges2004_idle.gif"],
    },
    "repetition": {
        "label": "Sec. 6: repetition",
        "prep": True,
        "keys": [
            "seed",
            "repetition",
            "perlin_frequency_hz",
            "figure_subjects",
            "extrema_pc",
            "analysis.extrema_eps_sd",
        ],
        "mem_mb": 4000,
        "outputs": {
            "extrema": in_report(
                "results/{dataset}/figures/egges2004_pc_extrema.png",
                "egges2004",
                "../report/egges2004_pc_extrema.rst",
                figure="Fig. 7-8",
                kind="figure",
            )
        },
        "extra": ["results/{dataset}/figures/egges2004_pc_extrema.png"],
    },
    "fitting": {
        "label": "Sec. 5.4.4, Fig. 4-5: fitting",
        "prep": False,
        "keys": ["seed", "fitting"],
        "mem_mb": 3000,
        "outputs": {},
        "extra": [
            "results/{dataset}/figures/egges2004_category_graph.png",
            "results/{dataset}/tables/egges2004_categories.csv",
        ],
    },
    "speed": {
        "label": "Sec. 8: real time",
        "prep": False,
        "keys": ["seed", "speed"],
        "mem_mb": 3000,
        "outputs": {},
        "extra": [],
    },
}

for _ev, _spec in EGGES_EVALUATIONS.items():
    register_evaluation(f"egges2004_{_ev}", paper="egges2004", extra=_spec["extra"])


rule egges2004_model:
    input:
        **EGGES_PREP,
    output:
        **EGGES_MODEL,
        categories=in_report(
            "results/{dataset}/tables/egges2004_categories.csv",
            "egges2004",
            "../report/egges2004_categories.rst",
            figure="Sec. 5.1, 5.3: categories vs ground truth",
            kind="table",
        ),
        graph=in_report(
            "results/{dataset}/figures/egges2004_category_graph.png",
            "egges2004",
            "../report/egges2004_category_graph.rst",
            figure="Fig. 3",
            kind="figure",
        ),
    params:
        options=config_params(
            "egges2004", ["seed", "held_out_clips", "translation_scale", "analysis", "figure_subjects"]
        ),
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("egges2004_model"),
    benchmark:
        ev_benchmark("egges2004_model")
    threads: 1
    resources:
        mem_mb=4000,
    conda:
        ENV
    script:
        "../scripts/egges2004_model.py"


# One rule per evaluation: table, figure and claims (plus the outputs of its spec).
for _ev, _spec in EGGES_EVALUATIONS.items():
    _name = f"egges2004_{_ev}"

    rule:
        name:
            _name
        input:
            **EGGES_MODEL,
            **(EGGES_PREP if _spec["prep"] else {}),
        output:
            table=in_report(
                ev_table(_name),
                "egges2004",
                f"../report/{_name}.rst",
                figure=_spec["label"],
                kind="table",
            ),
            figure=in_report(
                ev_figure(_name),
                "egges2004",
                f"../report/{_name}.rst",
                figure=_spec["label"],
                kind="figure",
            ),
            claims=ev_claims(_name),
            **_spec["outputs"],
        params:
            evaluation=_name,  # names the script: evaluated when the job runs, after the loop
            options=config_params("egges2004", _spec["keys"]),
            **({"joint_map": lambda wc: joint_map_path(wc.dataset)} if _spec["prep"] else {}),
        log:
            ev_log(_name),
        benchmark:
            ev_benchmark(_name)
        threads: 1
        resources:
            mem_mb=_spec["mem_mb"],
        conda:
            ENV
        script:
            "../scripts/{params.evaluation}.py"


rule egges2004_animation:
    input:
        **EGGES_MODEL,
    output:
        in_report(
            "results/{dataset}/figures/egges2004_idle.gif",
            "egges2004",
            "../report/egges2004_idle.rst",
            figure="generated idle motion per subject",
            kind="animation",
        ),
    params:
        options=config_params("egges2004", ["seed", "animation", "figure_subjects"]),
    log:
        ev_log("egges2004_animation"),
    benchmark:
        ev_benchmark("egges2004_animation")
    threads: 1
    resources:
        mem_mb=2000,
    conda:
        ENV
    script:
        "../scripts/egges2004_animation.py"
