# Du 2022 ch. 4, Morphable Graph (Herrmann et al. 2017): motion primitives (DTW + SFPCA +
# GMM/BIC) fitted to the primitives of the prep stage, space-partitioning tree search
# (Fig. 4.12), sample diversity (Fig. 4.9), constrained synthesis (Fig. 4.10) and
# compactness (Sec. 4.6.1). Options: config.graph (config/schema.yaml).


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
        options=config_params("graph", ["dense_picks_per_subject", "dense_grid_spacing_cm"]),
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
        options=graph_params("model", keys=["seed"]),
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
        settings=config_params(
            "graph",
            ["seed"]
            + [
                f"search.{k}"
                for k in ("n_samples", "n_queries", "beam", "beams", "max_evaluations", "leaf_size", "n_random")
            ],
        ),
        joints=config_params("graph", ["search.joints", "search.default_joint", "search.pose_joints"]),
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
        options=graph_params("synthesis", keys=["seed"]),
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


# The evaluations (tables, figures, claims): one rule each, same body; evaluation ->
# (published figure, inputs, params, mem_mb, further outputs). Script: ../scripts/<evaluation>.py.
# The script path comes from params.evaluation: Snakemake resolves a script path again when
# a job runs, when a loop variable holds the last name any loop gave it.
GRAPH_JOINT_MAP = {"joint_map": lambda wc: joint_map_path(wc.dataset)}
GRAPH_EVALUATIONS = {
    "du2022_fig4_12": ("Fig. 4.12", {"queries": graph_search_tables}, {}, 2000, {}),
    "du2022_fig4_9": (
        "Fig. 4.9",
        {"models": graph_diversity_models, "clips": f"{PREP}/clips.npz", "metadata": f"{PREP}/metadata.csv",
         "joint_map": joint_map_input},
        {"options": graph_params("diversity", keys=["seed"]), **GRAPH_JOINT_MAP},
        3000,
        {},
    ),
    "du2022_sec4_6_1": (
        "Sec. 4.6.1",
        {"models": graph_all_models, "metadata": f"{PREP}/metadata.csv", "dense": graph_dense_metadata},
        {},
        2000,
        {},
    ),
    "du2022_fig4_10": (
        "Fig. 4.10",
        {"models": graph_synthesis_models, "clips": f"{PREP}/clips.npz", "metadata": f"{PREP}/metadata.csv",
         "joint_map": joint_map_input},
        {"options": graph_params("synthesis", keys=["seed"]), **GRAPH_JOINT_MAP},
        3000,
        {"gif": "results/{dataset}/figures/du2022_fig4_10.gif"},
    ),
}

for _ev, (_figure, _input, _params, _mem_mb, _extra) in GRAPH_EVALUATIONS.items():
    register_evaluation(_ev, paper="du2022", extra=list(_extra.values()))

    rule:
        name:
            _ev
        input:
            **_input,
        output:
            table=in_report(ev_table(_ev), "du2022", f"../report/{_ev}.rst", figure=_figure, kind="table"),
            figure=in_report(ev_figure(_ev), "du2022", f"../report/{_ev}.rst", figure=_figure, kind="figure"),
            claims=ev_claims(_ev),
            **{k: in_report(p, "du2022", f"../report/{_ev}.rst", figure=_figure, kind="animation")
               for k, p in _extra.items()},
        params:
            evaluation=_ev,  # names the script (a script path is resolved again when the job runs)
            **_params,
        log:
            ev_log(_ev),
        benchmark:
            ev_benchmark(_ev)
        threads: 1
        resources:
            mem_mb=_mem_mb,
        conda:
            ENV
        script:
            "../scripts/{params.evaluation}.py"
