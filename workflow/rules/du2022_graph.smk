# Du 2022 ch. 4, Morphable Graph (Herrmann et al. 2017): motion primitives (DTW + SFPCA +
# GMM/BIC) fitted to the primitives of the prep stage, space-partitioning tree search
# (Fig. 4.12), sample diversity (Fig. 4.9), constrained synthesis (Fig. 4.10) and
# compactness (Sec. 4.6.1). Options: config.du2022_graph, passed whole to every rule as params.settings;
# its script builds motionvar.du2022.graph.settings.GraphSettings from it (config/schema.yaml).


include: "du2022_graph_helpers.smk"


wildcard_constraints:
    primitive="[A-Za-z0-9_]+",


rule du2022_graph_dense_picks:
    input:
        joint_map=joint_map_input,
    output:
        clips=f"{GRAPH}/dense_picks/clips.npz",
        metadata=f"{GRAPH}/dense_picks/metadata.csv",
    params:
        entry=graph_dense_entry,
        settings=section_for("du2022_graph"),
        prep=config["prep"],
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("du2022_graph_dense_picks"),
    benchmark:
        ev_benchmark("du2022_graph_dense_picks")
    threads: 1
    resources:
        mem_mb=2000,
    conda:
        ENV
    script:
        "../scripts/du2022_graph_dense_picks.py"


rule du2022_graph_primitive:
    input:
        unpack(graph_primitive_input),
    output:
        model=f"{GRAPH}/{{primitive}}.npz",
        meta=f"{GRAPH}/{{primitive}}.json",
    params:
        settings=section_for("du2022_graph"),
    log:
        ev_log("du2022_graph_primitive", "{primitive}"),
    benchmark:
        ev_benchmark("du2022_graph_primitive", "{primitive}")
    priority: PRIORITY["du2022_graph_primitive"]
    threads: 1
    resources:
        mem_mb=4000,
    conda:
        ENV
    script:
        "../scripts/du2022_graph_primitive.py"


rule du2022_graph_search:
    input:
        model=f"{GRAPH}/{{primitive}}.npz",
        meta=f"{GRAPH}/{{primitive}}.json",
        joint_map=joint_map_input,
    output:
        queries=f"{GRAPH}/search/{{primitive}}.csv",
        trees=f"{GRAPH}/search/{{primitive}}_trees.csv",
    params:
        settings=section_for("du2022_graph"),
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("du2022_graph_search", "{primitive}"),
    benchmark:
        ev_benchmark("du2022_graph_search", "{primitive}")
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/du2022_graph_search.py"


# the graph's transitions and the synthesis settings, saved beside the primitives for
# `motionvar du2022 walk` (in the default target of every dataset: DATASET_MODELS)
rule du2022_graph_edges:
    input:
        metadata=f"{PREP}/metadata.csv",
        joint_map=joint_map_input,
    output:
        model=GRAPH_EDGES[0],
        settings=GRAPH_EDGES[1],
    params:
        settings=section_for("du2022_graph"),
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("du2022_graph_edges"),
    benchmark:
        ev_benchmark("du2022_graph_edges")
    threads: 1
    resources:
        mem_mb=1000,
    conda:
        ENV
    script:
        "../scripts/du2022_graph_edges.py"


# The input sets of the evaluations (motionvar.du2022.catalog; rules made by evaluations.smk).
GRAPH_PREP = {"clips": f"{PREP}/clips.npz", "metadata": f"{PREP}/metadata.csv"}
add_input_set("du2022_graph_queries", {"queries": graph_search_tables})
add_input_set("du2022_graph_diversity", {"models": graph_diversity_models, **GRAPH_PREP, "joint_map": joint_map_input})
# Sec. 4.6.1: the clips too, each primitive is refitted to half of its clips (model size at N and 2N clips)
add_input_set(
    "du2022_graph_sizes",
    {
        "models": graph_all_models,
        "metadata": f"{PREP}/metadata.csv",
        "dense": graph_dense_metadata,
        "clips": f"{PREP}/clips.npz",
        "dense_clips": lambda wc: [p.replace("metadata.csv", "clips.npz") for p in graph_dense_metadata(wc)],
    },
)
add_input_set("du2022_graph_synthesis", {"models": graph_synthesis_models, **GRAPH_PREP, "joint_map": joint_map_input})
add_to_evaluation(
    "du2022_fig4_10",
    outputs={
        "gif": in_report(
            "results/{dataset}/figures/du2022_fig4_10.gif",
            "du2022",
            "../report/du2022_fig4_10.rst",
            page="gif_page_du2022_fig4_10",
            figure="Fig. 4.10",
            kind="animation",
        )
    },
)
