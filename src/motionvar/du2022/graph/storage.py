"""The Morphable Graph's transitions on disk (Du 2022 Sec. 4.4, Fig. 4.6), beside its
motion primitives (each saved by :meth:`~.primitive.MotionPrimitive.save`), in the project's
one model format (:mod:`motionvar.io.model_file`): the edges and the start and end node
counts in ``<base>.npz``, the rig's joint map and the settings of graph-walk synthesis
(Algorithm 1: :class:`~.settings.SynthesisSettings`, config ``du2022_graph.synthesis``, and
``du2022_graph.seed``) in ``<base>.json``. With the primitives this is all path following needs: no motion data.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ...core.joint_map import JointMap
from ...io.model_file import load_model, model_base, save_model
from .morphable_graph import MorphableGraph

KIND = "du2022.MorphableGraph"
VERSION = 1


@dataclass
class SavedGraph:
    """A loaded graph (its ``primitives`` empty: load them by name), the rig's joint map and
    the synthesis settings it was saved with."""

    graph: MorphableGraph
    joint_map: JointMap
    settings: dict


def _counts(d: dict[str, int], p: str) -> dict[str, np.ndarray]:
    names = sorted(d)
    return {f"{p}.names": np.array(names, dtype=str), f"{p}.counts": np.array([d[n] for n in names], dtype=np.int64)}


def save_graph(
    path: str | Path, graph: MorphableGraph, joint_map: JointMap, settings: dict | None = None
) -> list[Path]:
    """Write the graph's edges and node counts (``<base>.npz``) with ``joint_map`` and the
    JSON-able synthesis ``settings`` (``<base>.json``); returns both paths."""
    table = graph.edge_table()
    arrays = {
        "edges.from": table["from"].to_numpy(dtype=str),
        "edges.to": table["to"].to_numpy(dtype=str),
        "edges.count": table["count"].to_numpy(dtype=np.int64),
        "nodes": np.array(graph.nodes, dtype=str),
        **_counts(graph.start_nodes, "start"),
        **_counts(graph.end_nodes, "end"),
    }
    info = {
        "kind": KIND,
        "version": VERSION,
        "joint_map": {"joints": dict(joint_map.joints), "groups": {g: list(v) for g, v in joint_map.groups.items()}},
        "settings": dict(settings or {}),
    }
    return save_model(path, arrays, info)


def load_graph(path: str | Path) -> SavedGraph:
    """Read a graph written by :func:`save_graph`; ValueError naming the file when it is
    not one (FileNotFoundError when a file is missing)."""
    a, info = load_model(path, kind=KIND)
    base = model_base(path)
    try:
        if info.get("version") != VERSION:
            raise ValueError(f"version {info.get('version')} (expected {VERSION})")
        edges: dict[str, dict[str, int]] = {str(n): {} for n in a["nodes"]}
        for f, t, n in zip(a["edges.from"], a["edges.to"], a["edges.count"]):
            edges.setdefault(str(f), {})[str(t)] = int(n)
        starts = {str(n): int(c) for n, c in zip(a["start.names"], a["start.counts"])}
        ends = {str(n): int(c) for n, c in zip(a["end.names"], a["end.counts"])}
        jm = JointMap.from_dict(info["joint_map"], origin=f"{base}.json")
        return SavedGraph(MorphableGraph(edges, starts, ends), jm, dict(info["settings"]))
    except (KeyError, TypeError, ValueError) as exc:
        raise ValueError(f"{base}.npz/.json: not a complete {KIND} ({exc!r}); rerun rule du2022_graph_edges") from exc
