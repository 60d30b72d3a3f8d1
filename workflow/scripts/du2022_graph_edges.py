"""Rule du2022_graph_edges (Du 2022 Sec. 4.4, Fig. 4.6): the Morphable Graph's transitions
(consecutive primitives of each clip of the prep metadata) with the rig's joint map and
the settings of graph-walk synthesis (config du2022_graph.synthesis and du2022_graph.seed), saved beside the motion
primitives (motionvar.du2022.graph.storage) for the `motionvar du2022 walk` command."""


def main(snakemake) -> None:
    import logging

    import pandas as pd
    from _rule import config_settings, joint_map

    from motionvar.du2022.graph import MorphableGraph
    from motionvar.du2022.graph.storage import save_graph

    settings = config_settings(snakemake, "du2022_graph")
    saved = {"seed": settings.seed, **settings.synthesis.to_dict()}
    graph = MorphableGraph.from_metadata(pd.read_csv(snakemake.input.metadata, dtype={"clip_id": str}))
    save_graph(snakemake.output.model, graph, joint_map(snakemake), settings=saved)
    logging.info("nodes %s; edges:\n%s", graph.nodes, graph.edge_table().to_string())


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
