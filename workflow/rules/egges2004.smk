# Egges, Molet, Magnenat-Thalmann 2004, "Personalised Real-time Idle Motion Synthesis":
# posture PCA (Sec. 3.2), one idle database per subject (Sec. 5-6), and the evaluations of
# Sec. 5.4 (fitting), 6 (repetition) and 8 (identification, real time). Options:
# config.idle (config/schema.yaml). Inputs: the idle clips of results/{dataset}/prep/.

EGGES = "results/{dataset}/models/egges2004"

register_evaluation(
    "egges2004_identification", paper="egges2004", extra=["results/{dataset}/figures/egges2004_idle.gif"]
)
register_evaluation(
    "egges2004_repetition", paper="egges2004", extra=["results/{dataset}/figures/egges2004_pc_extrema.png"]
)
register_evaluation(
    "egges2004_fitting",
    paper="egges2004",
    extra=[
        "results/{dataset}/figures/egges2004_category_graph.png",
        "results/{dataset}/tables/egges2004_categories.csv",
    ],
)
register_evaluation("egges2004_speed", paper="egges2004")


rule egges2004_model:
    input:
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
        joint_map=joint_map_input,
    output:
        model=f"{EGGES}/idle_model.pkl",
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
        options=config["idle"],
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


rule egges2004_identification:
    input:
        model=f"{EGGES}/idle_model.pkl",
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
        joint_map=joint_map_input,
    output:
        table=in_report(
            ev_table("egges2004_identification"),
            "egges2004",
            "../report/egges2004_identification.rst",
            figure="Sec. 8: person identification",
            kind="table",
        ),
        figure=in_report(
            ev_figure("egges2004_identification"),
            "egges2004",
            "../report/egges2004_identification.rst",
            figure="Sec. 8: person identification",
            kind="figure",
        ),
        claims=ev_claims("egges2004_identification"),
    params:
        options=config["idle"],
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("egges2004_identification"),
    benchmark:
        ev_benchmark("egges2004_identification")
    threads: 1
    resources:
        mem_mb=4000,
    conda:
        ENV
    script:
        "../scripts/egges2004_identification.py"


rule egges2004_repetition:
    input:
        model=f"{EGGES}/idle_model.pkl",
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
        joint_map=joint_map_input,
    output:
        table=in_report(
            ev_table("egges2004_repetition"),
            "egges2004",
            "../report/egges2004_repetition.rst",
            figure="Sec. 6: repetition",
            kind="table",
        ),
        figure=in_report(
            ev_figure("egges2004_repetition"),
            "egges2004",
            "../report/egges2004_repetition.rst",
            figure="Sec. 6: repetition",
            kind="figure",
        ),
        claims=ev_claims("egges2004_repetition"),
        extrema=in_report(
            "results/{dataset}/figures/egges2004_pc_extrema.png",
            "egges2004",
            "../report/egges2004_pc_extrema.rst",
            figure="Fig. 7-8",
            kind="figure",
        ),
    params:
        options=config["idle"],
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("egges2004_repetition"),
    benchmark:
        ev_benchmark("egges2004_repetition")
    threads: 1
    resources:
        mem_mb=4000,
    conda:
        ENV
    script:
        "../scripts/egges2004_repetition.py"


rule egges2004_fitting:
    input:
        model=f"{EGGES}/idle_model.pkl",
    output:
        table=in_report(
            ev_table("egges2004_fitting"),
            "egges2004",
            "../report/egges2004_fitting.rst",
            figure="Sec. 5.4.4, Fig. 4-5: fitting",
            kind="table",
        ),
        figure=in_report(
            ev_figure("egges2004_fitting"),
            "egges2004",
            "../report/egges2004_fitting.rst",
            figure="Sec. 5.4.4, Fig. 4-5: fitting",
            kind="figure",
        ),
        claims=ev_claims("egges2004_fitting"),
    params:
        options=config["idle"],
    log:
        ev_log("egges2004_fitting"),
    benchmark:
        ev_benchmark("egges2004_fitting")
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/egges2004_fitting.py"


rule egges2004_speed:
    input:
        model=f"{EGGES}/idle_model.pkl",
    output:
        table=in_report(
            ev_table("egges2004_speed"),
            "egges2004",
            "../report/egges2004_speed.rst",
            figure="Sec. 8: real time",
            kind="table",
        ),
        figure=in_report(
            ev_figure("egges2004_speed"),
            "egges2004",
            "../report/egges2004_speed.rst",
            figure="Sec. 8: real time",
            kind="figure",
        ),
        claims=ev_claims("egges2004_speed"),
    params:
        options=config["idle"],
    log:
        ev_log("egges2004_speed"),
    benchmark:
        ev_benchmark("egges2004_speed")
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/egges2004_speed.py"


rule egges2004_animation:
    input:
        model=f"{EGGES}/idle_model.pkl",
    output:
        in_report(
            "results/{dataset}/figures/egges2004_idle.gif",
            "egges2004",
            "../report/egges2004_idle.rst",
            figure="generated idle motion per subject",
            kind="animation",
        ),
    params:
        options=config["idle"],
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
