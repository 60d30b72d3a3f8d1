# Which evaluations a dataset supports, decided from its data (motionvar.applicability and
# each paper's requirements.py): checkpoint applicability reads the clips' and the
# primitives' metadata and the rig's joint map (hands and toes a rig may lack); the default target then asks for each supported evaluation's
# outputs and, for the others, for a "not applicable" table, figure and claim naming what
# the data lacks (rules not_applicable_<paper>). Included after every paper's rule file.


checkpoint applicability:
    input:
        data=f"{DATA}/metadata.csv",
        prep=f"{PREP}/metadata.csv",
        joint_map=joint_map_input,
    output:
        APPLICABILITY,
    params:
        evaluations=list(EVALUATIONS),
        joint_map=lambda wc: joint_map_path(wc.dataset),
        **{section: section_for(section) for section in ("ma2010", "du2022_fda", "du2022_graph", "du2022_style", "egges2004")},
    log:
        ev_log("applicability"),
    benchmark:
        ev_benchmark("applicability")
    threads: 1
    resources:
        mem_mb=1000,
    conda:
        ENV
    script:
        "../scripts/applicability.py"


for _na_paper in ("ma2010", "du2022", "egges2004"):

    rule:
        name:
            f"not_applicable_{_na_paper}"
        input:
            APPLICABILITY,
        output:
            table=in_report(not_applicable_outputs("{ev}")["table"], _na_paper, "../report/not_applicable.rst",
                            figure="not applicable", kind="table"),
            figure=in_report(not_applicable_outputs("{ev}")["figure"], _na_paper, "../report/not_applicable.rst",
                             figure="not applicable", kind="figure"),
            claims=not_applicable_outputs("{ev}")["claims"],
        wildcard_constraints:
            ev=f"{_na_paper}_\\w+",
        log:
            ev_log(f"not_applicable_{_na_paper}", "{ev}"),
        benchmark:
            ev_benchmark(f"not_applicable_{_na_paper}", "{ev}")
        threads: 1
        resources:
            mem_mb=500,
        conda:
            ENV
        script:
            "../scripts/not_applicable.py"
