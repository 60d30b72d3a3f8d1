"""Rule du2022_graph_search (Du 2022 Fig. 4.12, one primitive): random position,
orientation and pose constraints searched by the k-means, GMM and median trees, random
sampling and brute force; one row per query and method."""


def main(snakemake) -> None:
    import logging

    from _graph import joint_map, models
    from motionvar.du2022.graph.evaluations import SearchSettings, search_primitive

    p = snakemake.params
    (model,) = models([snakemake.input.model]).values()
    queries, trees = search_primitive(model, joint_map(snakemake), SearchSettings(**p.settings), **p.joints)
    queries.to_csv(snakemake.output.queries, index=False)
    trees.to_csv(snakemake.output.trees, index=False)
    logging.info("%s: %d queries; trees %s", model.name, len(queries), trees.to_dict("records"))


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
