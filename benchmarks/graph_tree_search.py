"""Constraint search in a motion primitive (Du 2022 Sec. 4.5.2, Fig. 4.12): k-means tree
(beam search, the thesis' method, at several beams), the median tree as DFKI's kd-tree
(median-sample nodes, greedy descent) and our median split with node means, against brute
force, and the exact search over precomputed key-frame poses (our option), in one run on
the same queries.

The primitive is fitted to synthetic two-hand picks (pick_reach segments of the
generator, several subjects); queries are right-hand position constraints at the last
canonical frame, met by fresh GMM samples. Prints per method: queries per second, mean
objective evaluations per query, median error; and the ratios against brute force with
back-projection and FK of all samples (the naive baseline).

    python benchmarks/graph_tree_search.py [--samples 10000] [--queries 200] [--beams 2 3 4]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from motionvar.core import cmu_joint_map
from motionvar.du2022.graph import (
    KeyFramePositionIndex, MedianKDTree, MotionPrimitive, Objective, PrimitiveOptions, SpacePartitioningTree,
)
from motionvar.du2022.graph import brute_force, random_constraints
from motionvar.prep import align_motions
from motionvar.synth.dense_picks import dense_pick_segments


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
    prim = MotionPrimitive.fit(clips, "pick_reach", PrimitiveOptions(n_components=20, sfpca_max_iter=0,
                                                                     gmm_components=(1, 4)))
    S = prim.sample(args.samples, 0)
    hand = jm.index(prim.skeleton, "right_hand")
    last = prim.n_frames - 1
    queries = random_constraints(prim, "position", args.queries, [hand], last, 1)
    print(f"primitive: {len(clips)} clips, latent d = {prim.n_latent}, {prim.gmm_.n_components} Gaussians; "
          f"{args.samples} samples, {args.queries} position queries")

    t0 = time.perf_counter()
    tree = SpacePartitioningTree(S, "kmeans", leaf_size=args.leaf_size)
    build_tree = time.perf_counter() - t0
    t0 = time.perf_counter()
    kd = MedianKDTree(S)
    build_kd = time.perf_counter() - t0
    median_means = SpacePartitioningTree(S, "median", leaf_size=args.leaf_size)
    t0 = time.perf_counter()
    index = KeyFramePositionIndex(prim, S, [last], [hand])
    build_index = time.perf_counter() - t0

    results = {}
    n_brute = max(10, args.queries // 10)  # the naive brute force is slow: a subset of the queries
    methods = [("brute force (back-projection + FK)", lambda c: brute_force(S, Objective(prim, [c])),
                queries[:n_brute])]
    methods += [(f"k-means tree, beam {b}", lambda c, b=b: tree.search(Objective(prim, [c]), b), queries)
                for b in args.beams]
    methods += [
        ("median tree (DFKI kd-tree, greedy)", lambda c: kd.search(Objective(prim, [c])), queries),
        (f"median split, node means, beam {args.beams[0]}",
         lambda c: median_means.search(Objective(prim, [c]), args.beams[0]), queries),
        ("exact, precomputed key-frame poses", lambda c: index.search([c]), queries),
    ]
    for name, fn, qs in methods:
        t0 = time.perf_counter()
        out = [fn(c) for c in qs]
        dt = time.perf_counter() - t0
        results[name] = dict(qps=len(qs) / dt, evals=np.mean([r.n_evals for r in out]),
                             err=np.median([r.error for r in out]))
    base = results["brute force (back-projection + FK)"]
    print(f"(the naive brute force runs the first {n_brute} queries only; its error equals the exact search's there)")
    print(f"build: k-means tree {build_tree:.2f} s ({tree.n_nodes} nodes, depth {tree.depth}); kd-tree {build_kd:.2f} s "
          f"(depth {kd.depth}); key-frame index {build_index:.2f} s")
    print(f"{'method':40s} {'queries/s':>10s} {'x brute':>8s} {'evals':>8s} {'evals/brute':>11s} {'median err cm':>14s}")
    for name, r in results.items():
        ratio_e = r["evals"] / base["evals"] if base["evals"] else float("nan")
        print(f"{name:40s} {r['qps']:10.1f} {r['qps'] / base['qps']:8.1f} {r['evals']:8.1f} {ratio_e:11.4f} "
              f"{r['err']:14.3f}")
    exact = np.array([index.search([c]).error for c in queries])
    for b in args.beams:
        treeq = np.array([tree.search(Objective(prim, [c]), b).error for c in queries])
        print(f"k-means beam {b}: median of tree error / exact error {np.median(treeq / np.maximum(exact, 1e-9)):.2f}")


if __name__ == "__main__":
    main()
