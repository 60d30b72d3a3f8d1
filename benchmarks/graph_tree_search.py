"""Constraint search in a motion primitive (Du 2022 Sec. 4.5.2, Fig. 4.12): k-means tree
(beam search, the thesis' method, at several beams), the median tree as DFKI's kd-tree
(median-sample nodes, greedy descent) and our median split with node means, against brute
force, and the exact search over precomputed key-frame poses (our option), in one run on
the same queries.

Each tree search runs two ways: one query at a time on the Eq. 4.2 objective (back-
projection and FK of every candidate batch, as in synthesis), and all queries in lockstep
on precomputed key-frame poses of the tree's samples and node means (``search_many`` with
``KeyFramePositionIndex.objective_many``: one vectorised call per tree level, as rule
du2022_graph_search runs them); random sampling likewise (``random_search`` per query,
``random_search_many``). The two give the same sample, error and evaluation count per
query (checked here; ``identical`` column), so the ``x one-at-a-time`` column is a pure
speed ratio, measured in the same run.

The primitive is fitted to synthetic two-hand picks (pick_reach segments of the
generator, several subjects); queries are right-hand position constraints at the last
canonical frame, met by fresh GMM samples. Prints per method: queries per CPU second,
mean objective evaluations per query, median error; and the ratios against brute force
with back-projection and FK of all samples (the naive baseline).

    python benchmarks/graph_tree_search.py [--samples 10000] [--queries 200] [--beams 2 3 4]
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable, Sequence

import numpy as np

from motionvar.core import cmu_joint_map
from motionvar.du2022.graph import (
    Constraint,
    KeyFramePositionIndex,
    MedianKDTree,
    MotionPrimitive,
    Objective,
    PrimitiveOptions,
    SearchResult,
    SpacePartitioningTree,
    brute_force,
    random_constraints,
    random_search,
)
from motionvar.du2022.graph.constraints import ConstraintStack
from motionvar.du2022.graph.trees import random_search_many
from motionvar.prep import align_motions
from motionvar.synth.dense_picks import dense_pick_segments

Searches = Callable[[Sequence[Constraint]], list[SearchResult]]


def _same(a: list[SearchResult], b: list[SearchResult]) -> bool:
    return all(
        (x.index, x.error, x.n_evals) == (y.index, y.error, y.n_evals) and np.array_equal(x.latent, y.latent)
        for x, y in zip(a, b)
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=10000)
    parser.add_argument("--queries", type=int, default=200)
    parser.add_argument("--beams", type=int, nargs="+", default=[2, 3, 4])
    parser.add_argument("--leaf-size", type=int, default=16)
    parser.add_argument("--subjects", type=int, default=6)
    args = parser.parse_args()

    jm = cmu_joint_map()
    clips = align_motions(dense_pick_segments(args.subjects, 0, 5)[0], jm)
    prim = MotionPrimitive(
        "pick_reach", PrimitiveOptions(n_components=20, sfpca_max_iter=0, gmm_components=(1, 4))
    ).fit(clips)
    S = prim.sample(args.samples, 0)
    hand = jm.index(prim.skeleton, "right_hand")
    last = prim.n_frames - 1
    queries = random_constraints(prim, "position", args.queries, [hand], last, 1)
    print(
        f"primitive: {len(clips)} clips, latent d = {prim.n_latent}, {prim.gmm_.n_components} Gaussians; "
        f"{args.samples} samples, {args.queries} position queries"
    )

    t0 = time.process_time()
    tree = SpacePartitioningTree(S, "kmeans", leaf_size=args.leaf_size)
    build_tree = time.process_time() - t0
    t0 = time.process_time()
    kd = MedianKDTree(S)
    build_kd = time.process_time() - t0
    median_means = SpacePartitioningTree(S, "median", leaf_size=args.leaf_size)
    t0 = time.process_time()
    index = KeyFramePositionIndex(prim, S, [last], [hand])
    build_index = time.process_time() - t0
    t0 = time.process_time()
    poses = {t: KeyFramePositionIndex(prim, t.points, [last], [hand]) for t in (tree, median_means)}
    build_poses = time.process_time() - t0
    stack = ConstraintStack([[c] for c in queries])

    def each(fn: Callable[[Constraint], SearchResult]) -> Searches:
        return lambda qs: [fn(c) for c in qs]

    def lockstep(t: SpacePartitioningTree, b: int) -> Searches:
        return lambda qs: t.search_many(poses[t].objective_many(stack), len(qs), b)

    def random_each(qs: Sequence[Constraint]) -> list[SearchResult]:
        rng = np.random.default_rng(2)  # the stream random_search_many draws from
        return [random_search(prim, Objective(prim, [c]), 100, rng) for c in qs]

    n_brute = max(10, args.queries // 10)  # the naive brute force is slow: a subset of the queries
    # (name, one query at a time, all queries at once or None)
    methods: list[tuple[str, Searches, Searches | None]] = [
        ("brute force (back-projection + FK)", each(lambda c: brute_force(S, Objective(prim, [c]))), None)
    ]
    methods += [
        (f"k-means tree, beam {b}", each(lambda c, b=b: tree.search(Objective(prim, [c]), b)), lockstep(tree, b))
        for b in args.beams
    ]
    methods += [
        (
            "median tree (DFKI kd-tree, greedy)",
            each(lambda c: kd.search(Objective(prim, [c]))),
            lambda qs: kd.search_many(index.objective_many(stack), len(qs)),
        ),
        (
            f"median split, node means, beam {args.beams[0]}",
            each(lambda c: median_means.search(Objective(prim, [c]), args.beams[0])),
            lockstep(median_means, args.beams[0]),
        ),
        (
            "random, 100 fresh samples",
            random_each,
            lambda qs: random_search_many(prim, [[c] for c in qs], 100, np.random.default_rng(2)),
        ),
        ("exact, precomputed key-frame poses", each(lambda c: index.search([c])), None),
    ]
    results = {}
    for name, one, many in methods:
        qs = queries[:n_brute] if name.startswith("brute") else queries
        t0 = time.process_time()
        out = one(qs)
        dt = time.process_time() - t0
        row = dict(qps=len(qs) / dt, evals=np.mean([r.n_evals for r in out]), err=np.median([r.error for r in out]))
        if many is not None:
            t0 = time.process_time()
            batched = many(qs)
            row.update(qps_many=len(qs) / (time.process_time() - t0), identical=_same(out, batched))
        results[name] = row
    base = results["brute force (back-projection + FK)"]
    print(f"(the naive brute force runs the first {n_brute} queries only; its error equals the exact search's there)")
    print(
        f"build (CPU s): k-means tree {build_tree:.2f} ({tree.n_nodes} nodes, depth {tree.depth}); kd-tree "
        f"{build_kd:.2f} (depth {kd.depth}); key-frame index {build_index:.2f}; poses of the trees' node means and "
        f"samples (lockstep) {build_poses:.2f}"
    )
    print(
        f"{'method':40s} {'queries/s':>10s} {'x brute':>8s} {'evals':>8s} {'evals/brute':>11s} {'median err cm':>14s}"
        f" {'lockstep q/s':>13s} {'x one-at-a-time':>16s} {'identical':>10s}"
    )
    for name, r in results.items():
        ratio_e = r["evals"] / base["evals"] if base["evals"] else float("nan")
        many = (
            f" {r['qps_many']:13.1f} {r['qps_many'] / r['qps']:16.1f} {str(r['identical']):>10s}"
            if "qps_many" in r
            else ""
        )
        print(
            f"{name:40s} {r['qps']:10.1f} {r['qps'] / base['qps']:8.1f} {r['evals']:8.1f} {ratio_e:11.4f} "
            f"{r['err']:14.3f}{many}"
        )
    exact = np.array([index.search([c]).error for c in queries])
    for b in args.beams:
        treeq = np.array([r.error for r in tree.search_many(poses[tree].objective_many(stack), len(queries), b)])
        print(f"k-means beam {b}: median of tree error / exact error {np.median(treeq / np.maximum(exact, 1e-9)):.2f}")


if __name__ == "__main__":
    main()
