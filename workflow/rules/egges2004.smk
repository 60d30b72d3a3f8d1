# Egges, Molet, Magnenat-Thalmann 2004, "Personalised Real-time Idle Motion Synthesis":
# posture PCA (Sec. 3.2), one idle database per subject (Sec. 5-6), and the evaluations of
# Sec. 5.4 (fitting), 6 (repetition) and 8 (identification, real time): one rule each, made by
# evaluations.smk from the declarations of motionvar.egges2004.catalog. Every rule gets config
# section egges2004 as params.settings (motionvar.egges2004.settings.Egges2004Settings; section_for:
# less the keys one evaluation owns). Inputs:
# the idle clips of results/{dataset}/prep/. Library: motionvar.egges2004 (the method,
# pipeline, storage), its evaluations/ and figures.

EGGES = "results/{dataset}/models/egges2004"
# the fitted model of all subjects: arrays and settings (motionvar.egges2004.storage)
EGGES_MODEL = {"model": f"{EGGES}/idle_model.npz", "model_settings": f"{EGGES}/idle_model.json"}
EGGES_PREP = {"clips": f"{PREP}/clips.npz", "metadata": f"{PREP}/metadata.csv", "joint_map": joint_map_input}

EGGES_JOINT_MAP = {"joint_map": lambda wc: joint_map_path(wc.dataset)}

# the input sets of the evaluations (motionvar.egges2004.catalog; rules made by evaluations.smk):
# the fitted model, with the prep dataset's recordings (training and held out) where one needs them
add_input_set("egges2004_recordings", {**EGGES_MODEL, **EGGES_PREP})
add_input_set("egges2004_training", {**EGGES_MODEL, **EGGES_PREP})
add_input_set("egges2004_model", EGGES_MODEL)
add_to_evaluation("egges2004_identification", extra=("results/{dataset}/figures/egges2004_idle.gif",))
add_to_evaluation(
    "egges2004_repetition",
    outputs={
        "extrema": in_report(
            "results/{dataset}/figures/egges2004_pc_extrema.png",
            "egges2004",
            "../report/egges2004_pc_extrema.rst",
            figure="Fig. 7-8",
            kind="figure",
        )
    },
)
add_to_evaluation(
    "egges2004_fitting",
    extra=(
        "results/{dataset}/figures/egges2004_category_graph.png",
        "results/{dataset}/tables/egges2004_categories.csv",
    ),
)


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
        settings=section_for("egges2004"),
        **EGGES_JOINT_MAP,
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


rule egges2004_animation:
    input:
        **EGGES_MODEL,
    output:
        in_report(
            "results/{dataset}/figures/egges2004_idle.gif",
            "egges2004",
            "../report/egges2004_idle.rst",
            page="gif_page_egges2004_idle",
            figure="generated idle motion per subject",
            kind="animation",
        ),
    params:
        settings=section_for("egges2004"),
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
