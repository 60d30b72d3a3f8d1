# Du 2022 ch. 4, Morphable Graph (Herrmann et al. 2017): motion primitives (DTW + SFPCA +
# GMM/BIC) fitted to the primitives of the prep stage, space-partitioning tree search
# (Fig. 4.12), sample diversity (Fig. 4.9), constrained synthesis (Fig. 4.10) and
# compactness (Sec. 4.6.1). Options: config.graph (config/schema.yaml).


include: "du2022_graph_helpers.smk"


register_evaluation("du2022_fig4_12", paper="du2022")
register_evaluation("du2022_fig4_9", paper="du2022")
register_evaluation("du2022_sec4_6_1", paper="du2022")
register_evaluation("du2022_fig4_10", paper="du2022", extra=["results/{dataset}/figures/du2022_fig4_10.gif"])


wildcard_constraints:
    primitive="[A-Za-z0-9_]+",


rule graph_dense_picks:
    input:
        joint_map=joint_map_input,
    output:
        clips=f"{GRAPH}/dense_picks/clips.npz",
        metadata=f"{GRAPH}/dense_picks/metadata.csv",
    params:
        entry=lambda wc: dataset_config(wc.dataset),
        options=GRAPH_CFG,
        prep=config["prep"],
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("graph_dense_picks"),
    benchmark:
        ev_benchmark("graph_dense_picks")
    threads: 1
    resources:
        mem_mb=2000,
    conda:
        ENV
    script:
        "../scripts/graph_dense_picks.py"


rule graph_primitive:
    input:
        unpack(graph_primitive_input),
    output:
        model=f"{GRAPH}/{{primitive}}.npz",
        meta=f"{GRAPH}/{{primitive}}.json",
    params:
        options=GRAPH_CFG,
    log:
        ev_log("graph_primitive", "{primitive}"),
    benchmark:
        ev_benchmark("graph_primitive", "{primitive}")
    threads: 1
    resources:
        mem_mb=4000,
    conda:
        ENV
    script:
        "../scripts/graph_primitive.py"


rule graph_search:
    input:
        model=f"{GRAPH}/{{primitive}}.npz",
        meta=f"{GRAPH}/{{primitive}}.json",
        joint_map=joint_map_input,
    output:
        queries=f"{GRAPH}/search/{{primitive}}.csv",
        trees=f"{GRAPH}/search/{{primitive}}_trees.csv",
    params:
        options=GRAPH_CFG,
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("graph_search", "{primitive}"),
    benchmark:
        ev_benchmark("graph_search", "{primitive}")
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/graph_search.py"


rule du2022_fig4_12:
    input:
        queries=graph_search_tables,
    output:
        table=in_report(
            ev_table("du2022_fig4_12"), "du2022", "../report/du2022_fig4_12.rst", figure="Fig. 4.12", kind="table"
        ),
        figure=in_report(
            ev_figure("du2022_fig4_12"), "du2022", "../report/du2022_fig4_12.rst", figure="Fig. 4.12", kind="figure"
        ),
        claims=ev_claims("du2022_fig4_12"),
    log:
        ev_log("du2022_fig4_12"),
    benchmark:
        ev_benchmark("du2022_fig4_12")
    threads: 1
    resources:
        mem_mb=2000,
    conda:
        ENV
    script:
        "../scripts/du2022_fig4_12.py"


rule du2022_fig4_9:
    input:
        walk=f"{GRAPH}/walk_leftStance.npz",
        walk_meta=f"{GRAPH}/walk_leftStance.json",
        pick=f"{GRAPH}/pick_reach.npz",
        pick_meta=f"{GRAPH}/pick_reach.json",
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
        joint_map=joint_map_input,
    output:
        table=in_report(
            ev_table("du2022_fig4_9"), "du2022", "../report/du2022_fig4_9.rst", figure="Fig. 4.9", kind="table"
        ),
        figure=in_report(
            ev_figure("du2022_fig4_9"), "du2022", "../report/du2022_fig4_9.rst", figure="Fig. 4.9", kind="figure"
        ),
        claims=ev_claims("du2022_fig4_9"),
    params:
        options=GRAPH_CFG,
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("du2022_fig4_9"),
    benchmark:
        ev_benchmark("du2022_fig4_9")
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/du2022_fig4_9.py"


rule du2022_sec4_6_1:
    input:
        models=graph_all_models,
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
    output:
        table=in_report(
            ev_table("du2022_sec4_6_1"), "du2022", "../report/du2022_sec4_6_1.rst", figure="Sec. 4.6.1", kind="table"
        ),
        figure=in_report(
            ev_figure("du2022_sec4_6_1"), "du2022", "../report/du2022_sec4_6_1.rst", figure="Sec. 4.6.1",
            kind="figure",
        ),
        claims=ev_claims("du2022_sec4_6_1"),
    params:
        options=GRAPH_CFG,
    log:
        ev_log("du2022_sec4_6_1"),
    benchmark:
        ev_benchmark("du2022_sec4_6_1")
    threads: 1
    resources:
        mem_mb=2000,
    conda:
        ENV
    script:
        "../scripts/du2022_sec4_6_1.py"


rule du2022_fig4_10:
    input:
        models=graph_synthesis_models,
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
        joint_map=joint_map_input,
    output:
        table=in_report(
            ev_table("du2022_fig4_10"), "du2022", "../report/du2022_fig4_10.rst", figure="Fig. 4.10", kind="table"
        ),
        figure=in_report(
            ev_figure("du2022_fig4_10"), "du2022", "../report/du2022_fig4_10.rst", figure="Fig. 4.10", kind="figure"
        ),
        gif=in_report(
            "results/{dataset}/figures/du2022_fig4_10.gif", "du2022", "../report/du2022_fig4_10.rst",
            figure="Fig. 4.10", kind="animation",
        ),
        claims=ev_claims("du2022_fig4_10"),
    params:
        options=GRAPH_CFG,
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("du2022_fig4_10"),
    benchmark:
        ev_benchmark("du2022_fig4_10")
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/du2022_fig4_10.py"
