# Helpers of du2022_graph.smk (Du 2022 ch. 4, Morphable Graph), kept apart from its rules
# (snakemake --lint flags a rule file that defines functions).

GRAPH_CFG = config["du2022_graph"]
GRAPH = "results/{dataset}/models/du2022/graph"
GRAPH_DENSE = "pick_reach_dense"
# the graph's transitions, written by rule du2022_graph_edges (motionvar.du2022.graph.storage), read by
# `motionvar du2022 walk`; a folder of its own (a file beside the primitives would match
# {primitive}); it needs only the prep metadata, so every dataset gets it (DATASET_MODELS)
GRAPH_EDGES = [f"{GRAPH}/graph/edges.npz", f"{GRAPH}/graph/edges.json"]
DATASET_MODELS.extend((p, ()) for p in GRAPH_EDGES)


def graph_dense_entry(wildcards):
    """What the dense picks read of the dataset's entry: its source, subjects and seed."""
    entry = dataset_config(wildcards.dataset)
    return {k: entry.get(k) for k in ("source", "subjects", "seed")}


def graph_has_dense(dataset):
    """The dense-grid picking primitive (Fig. 4.11) exists for synthetic datasets only."""
    return dataset_config(dataset)["source"] == "synthetic" and GRAPH_CFG["dense_picks_per_subject"] > 0


def graph_search_primitives(dataset):
    """Primitives of the Fig. 4.12 search comparison."""
    extra = [GRAPH_DENSE] if graph_has_dense(dataset) else []
    return list(GRAPH_CFG["search"]["primitives"]) + extra


def graph_all_primitives(dataset):
    """Every modelled primitive of a dataset (the graph's nodes, plus the dense one)."""
    extra = [GRAPH_DENSE] if graph_has_dense(dataset) else []
    return list(dict.fromkeys(list(GRAPH_CFG["primitives"]) + list(GRAPH_CFG["search"]["primitives"]) + extra))


def graph_model_files(dataset, primitives):
    base = GRAPH.format(dataset=dataset)
    return [f"{base}/{p}.{ext}" for p in primitives for ext in ("npz", "json")]


def graph_primitive_input(wildcards):
    """Clips of one primitive: the dense picks for the dense one, else the prep stage."""
    if wildcards.primitive == GRAPH_DENSE:
        base = f"{GRAPH}/dense_picks".format(dataset=wildcards.dataset)
    else:
        base = PREP.format(dataset=wildcards.dataset)
    return {"clips": f"{base}/clips.npz", "metadata": f"{base}/metadata.csv"}


def graph_search_tables(wildcards):
    base = GRAPH.format(dataset=wildcards.dataset)
    return [f"{base}/search/{p}.csv" for p in graph_search_primitives(wildcards.dataset)]


def graph_all_models(wildcards):
    return graph_model_files(wildcards.dataset, graph_all_primitives(wildcards.dataset))


def graph_dense_metadata(wildcards):
    """The dense picks' metadata, where the dataset has the dense primitive (Sec. 4.6.1)."""
    if not graph_has_dense(wildcards.dataset):
        return []
    return [f"{GRAPH}/dense_picks/metadata.csv".format(dataset=wildcards.dataset)]


def graph_diversity_models(wildcards):
    """Models of Fig. 4.9: walk leftStance and pick reach."""
    return graph_model_files(wildcards.dataset, ["walk_leftStance", "pick_reach"])


def graph_synthesis_models(wildcards):
    """Models of Fig. 4.10: the walking primitives of the graph and the reaching one."""
    walk = [p for p in GRAPH_CFG["primitives"] if p.startswith("walk_")]
    return graph_model_files(wildcards.dataset, walk + [GRAPH_CFG["synthesis"]["reach_primitive"]])
