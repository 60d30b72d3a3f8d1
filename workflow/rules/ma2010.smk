# Ma et al. 2010, "Modeling Style and Variation in Human Motion": walking cycles cut at
# the key frames (Sec. 4), the hierarchical model (Sec. 5-6) and its evaluations
# (Fig. 3, 6, 7b, 8, Sec. 7.4, Sec. 8). Options: config.ma2010 (config/schema.yaml).

MA2010 = "results/{dataset}/models/ma2010"

for _ev in ("ma2010_fig3", "ma2010_fig6", "ma2010_fig7b", "ma2010_fig8", "ma2010_sec8"):
    register_evaluation(_ev, paper="ma2010")
register_evaluation("ma2010_sec7_4", paper="ma2010", extra=["results/{dataset}/figures/ma2010_sec7_4.gif"])


rule ma2010_clips:
    input:
        clips=f"{DATA}/clips.npz",
        metadata=f"{DATA}/metadata.csv",
        joint_map=joint_map_input,
    output:
        clips=f"{MA2010}/walk_clips.npz",
        table=f"{MA2010}/walk_cycles.csv",
    params:
        options=config["ma2010"],
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("ma2010_clips"),
    benchmark:
        ev_benchmark("ma2010_clips")
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/ma2010_clips.py"


rule ma2010_fig3:
    input:
        clips=f"{DATA}/clips.npz",
        metadata=f"{DATA}/metadata.csv",
        joint_map=joint_map_input,
    output:
        table=in_report(ev_table("ma2010_fig3"), "ma2010", "../report/ma2010_fig3.rst", figure="Fig. 3", kind="table"),
        figure=in_report(ev_figure("ma2010_fig3"), "ma2010", "../report/ma2010_fig3.rst", figure="Fig. 3", kind="figure"),
        claims=ev_claims("ma2010_fig3"),
    params:
        options=config["ma2010"],
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("ma2010_fig3"),
    benchmark:
        ev_benchmark("ma2010_fig3")
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/ma2010_fig3.py"


rule ma2010_fig6:
    input:
        clips=f"{MA2010}/walk_clips.npz",
        table=f"{MA2010}/walk_cycles.csv",
        joint_map=joint_map_input,
    output:
        table=in_report(ev_table("ma2010_fig6"), "ma2010", "../report/ma2010_fig6.rst", figure="Fig. 6", kind="table"),
        figure=in_report(ev_figure("ma2010_fig6"), "ma2010", "../report/ma2010_fig6.rst", figure="Fig. 6", kind="figure"),
        claims=ev_claims("ma2010_fig6"),
    params:
        options=config["ma2010"],
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("ma2010_fig6"),
    benchmark:
        ev_benchmark("ma2010_fig6")
    threads: 1
    resources:
        mem_mb=4000,
    conda:
        ENV
    script:
        "../scripts/ma2010_fig6.py"


rule ma2010_fig7b:
    input:
        clips=f"{MA2010}/walk_clips.npz",
        table=f"{MA2010}/walk_cycles.csv",
        joint_map=joint_map_input,
    output:
        table=in_report(ev_table("ma2010_fig7b"), "ma2010", "../report/ma2010_fig7b.rst", figure="Fig. 7b", kind="table"),
        figure=in_report(ev_figure("ma2010_fig7b"), "ma2010", "../report/ma2010_fig7b.rst", figure="Fig. 7b", kind="figure"),
        claims=ev_claims("ma2010_fig7b"),
    params:
        options=config["ma2010"],
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("ma2010_fig7b"),
    benchmark:
        ev_benchmark("ma2010_fig7b")
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/ma2010_fig7b.py"


rule ma2010_fig8:
    input:
        clips=f"{MA2010}/walk_clips.npz",
        table=f"{MA2010}/walk_cycles.csv",
        joint_map=joint_map_input,
    output:
        table=in_report(ev_table("ma2010_fig8"), "ma2010", "../report/ma2010_fig8.rst", figure="Fig. 8a", kind="table"),
        figure=in_report(ev_figure("ma2010_fig8"), "ma2010", "../report/ma2010_fig8.rst", figure="Fig. 8a", kind="figure"),
        claims=ev_claims("ma2010_fig8"),
    params:
        options=config["ma2010"],
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("ma2010_fig8"),
    benchmark:
        ev_benchmark("ma2010_fig8")
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/ma2010_fig8.py"


rule ma2010_sec7_4:
    input:
        clips=f"{MA2010}/walk_clips.npz",
        table=f"{MA2010}/walk_cycles.csv",
        joint_map=joint_map_input,
    output:
        table=in_report(ev_table("ma2010_sec7_4"), "ma2010", "../report/ma2010_sec7_4.rst", figure="Sec. 7.4", kind="table"),
        figure=in_report(ev_figure("ma2010_sec7_4"), "ma2010", "../report/ma2010_sec7_4.rst", figure="Sec. 7.4", kind="figure"),
        animation=in_report(
            "results/{dataset}/figures/ma2010_sec7_4.gif", "ma2010", "../report/ma2010_sec7_4.rst", figure="Sec. 7.4",
            kind="animation",
        ),
        claims=ev_claims("ma2010_sec7_4"),
    params:
        options=config["ma2010"],
        joint_map=lambda wc: joint_map_path(wc.dataset),
        animation=config["report"],
    log:
        ev_log("ma2010_sec7_4"),
    benchmark:
        ev_benchmark("ma2010_sec7_4")
    threads: 2
    resources:
        mem_mb=4000,
    conda:
        ENV
    script:
        "../scripts/ma2010_sec7_4.py"


rule ma2010_sec8:
    input:
        clips=f"{MA2010}/walk_clips.npz",
        table=f"{MA2010}/walk_cycles.csv",
        joint_map=joint_map_input,
    output:
        table=in_report(ev_table("ma2010_sec8"), "ma2010", "../report/ma2010_sec8.rst", figure="Sec. 8", kind="table"),
        figure=in_report(ev_figure("ma2010_sec8"), "ma2010", "../report/ma2010_sec8.rst", figure="Sec. 8", kind="figure"),
        claims=ev_claims("ma2010_sec8"),
    params:
        options=config["ma2010"],
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("ma2010_sec8"),
    benchmark:
        ev_benchmark("ma2010_sec8")
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/ma2010_sec8.py"
