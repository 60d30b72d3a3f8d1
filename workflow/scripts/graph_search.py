"""Rule graph_search (Du 2022 Fig. 4.12, one primitive): random position, orientation
and pose constraints searched by the k-means, GMM and median trees, random sampling and
brute force; one row per query and method."""


def main(snakemake) -> None:
    import logging

    from _graph import joint_map, load_model, semantic_index
    from motionvar.du2022.graph.evaluation import SearchSettings, search_comparison

    o = snakemake.params.options
    s = o["search"]
    name = snakemake.wildcards.primitive
    model = load_model(snakemake.input.model)
    jm = joint_map(snakemake)
    sem = s["joints"].get(name, s["default_joint"])
    joint = semantic_index(jm, model.skeleton, sem, f"graph.search.joints.{name}")
    pose = [semantic_index(jm, model.skeleton, j, "graph.search.pose_joints") for j in s["pose_joints"]]
    settings = SearchSettings(n_samples=s["n_samples"], n_queries=s["n_queries"], beam=s["beam"],
                              leaf_size=s["leaf_size"], n_random=s["n_random"], seed=o["seed"])
    table, trees = search_comparison(model, joint, pose, settings)
    table.insert(0, "primitive", name)
    table.insert(2, "joint", sem)
    trees.insert(0, "primitive", name)
    table.to_csv(snakemake.output.queries, index=False)
    trees.to_csv(snakemake.output.trees, index=False)
    logging.info("%s: %d queries; trees %s", name, len(table), trees.to_dict("records"))


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
