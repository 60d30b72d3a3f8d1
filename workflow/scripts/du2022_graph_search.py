"""Rule du2022_graph_search (Du 2022 Fig. 4.12, one primitive): random position,
orientation and pose constraints searched by the k-means tree (at every beam measured),
the GMM tree, the median tree (a kd-tree, greedy and at the k-means tree's evaluations) and
our median split, random sampling and brute force; one row per query, method and beam
(column selected: the verdicts' beam, du2022_graph.search.beam; column budget_beam: the largest
k-means beam under the evaluation budget). Settings: config du2022_graph.search and du2022_graph.seed
(params.settings)."""


def main(snakemake) -> None:
    import logging

    from _graph import models
    from _rule import config_settings, joint_map

    from motionvar.du2022.graph.evaluations import search_primitive

    settings = config_settings(snakemake, "du2022_graph")
    (model,) = models([snakemake.input.model]).values()
    queries, trees = search_primitive(model, joint_map(snakemake), settings)
    queries.to_csv(snakemake.output.queries, index=False)
    trees.to_csv(snakemake.output.trees, index=False)
    km = queries[queries["method"] == "kmeans"]
    logging.info(
        "%s: %d queries; trees %s; k-means mean evaluations by beam %s, verdict beam %s, budget beam %s",
        model.name,
        len(queries),
        trees.to_dict("records"),
        km.groupby("beam")["n_evals"].mean().round(1).to_dict(),
        sorted(set(km.loc[km["selected"], "beam"])),
        sorted(set(km.loc[km["budget_beam"], "beam"])),
    )


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
