"""Batched evaluation in the Morphable Graph searches (Du 2022 Sec. 4.5.2, Fig. 4.12): many
queries at once (ConstraintStack, the lockstep ``search_many`` of the trees,
``random_search_many``), precomputed key-frame poses (KeyFramePositionIndex) and the GMM
log density give exactly (bit for bit) what one query, one latent vector batch or
scikit-learn's ``score_samples`` gives; the tree searches also match the per-query
reference loops they replaced (heapq.nsmallest beam, greedy kd descent), ties included."""

from __future__ import annotations

import heapq

import numpy as np
import pytest
from graph_toy import toy_clips

from motionvar.core import cmu_joint_map
from motionvar.du2022.graph import (
    Constraint,
    KeyFramePositionIndex,
    MedianKDTree,
    MotionPrimitive,
    Objective,
    PrimitiveOptions,
    SpacePartitioningTree,
    brute_force,
    random_constraints,
    random_search,
)
from motionvar.du2022.graph.constraints import ConstraintStack, constraint_errors
from motionvar.du2022.graph.primitive import gmm_log_density
from motionvar.du2022.graph.trees import random_search_many

OPT = PrimitiveOptions(n_basis=8, n_components=5, gmm_components=(2, 3), sfpca_max_iter=0)
KINDS = ("position", "orientation", "pose")


@pytest.fixture(scope="module")
def prim():
    return MotionPrimitive("walk_leftStance", OPT).fit(toy_clips(16))


@pytest.fixture(scope="module")
def setup(prim):
    """(samples, last frame, position joint, pose joints, all joints, queries by kind)."""
    jm = cmu_joint_map()
    hand = jm.index(prim.skeleton, "right_hand")
    pose = [jm.index(prim.skeleton, k) for k in ("hips", "left_hand", "right_hand", "left_ankle")]
    joints = [hand] + [j for j in pose if j != hand]
    last = prim.n_frames - 1
    queries = {k: random_constraints(prim, k, 12, [hand] if k != "pose" else pose, last, 7) for k in KINDS}
    return prim.sample(700, 3), last, hand, pose, joints, queries


def _reference_beam(tree: SpacePartitioningTree, objective, beam: int) -> tuple[int, float, int]:
    """The per-query beam search as it was before the lockstep one (heapq.nsmallest)."""
    frontier, n_evals, best = [0], 0, (np.inf, -1)
    while frontier:
        leaf_nodes = [n for n in frontier if n in tree.leaves]
        inner = [n for n in frontier if n not in tree.leaves]
        if leaf_nodes:
            idx = np.concatenate([tree.leaves[n] for n in leaf_nodes])
            err = objective(tree.samples[idx])
            n_evals += len(idx)
            i = int(np.argmin(err))
            if err[i] < best[0]:
                best = (float(err[i]), int(idx[i]))
        if not inner:
            break
        kids = np.concatenate([tree.children[n] for n in inner])
        err = objective(tree.means[kids])
        n_evals += len(kids)
        frontier = [int(kids[i]) for i in heapq.nsmallest(beam, range(len(kids)), key=err.__getitem__)]
    return best[1], best[0], n_evals


def _reference_greedy(tree: MedianKDTree, objective) -> tuple[int, float, int]:
    """The per-query greedy kd descent as it was before the lockstep one."""
    node, best_err = 0, float(objective(tree.samples[tree.point[:1]])[0])
    best, n_evals = int(tree.point[0]), 1
    while True:
        kids = [int(c) for c in (tree.left[node], tree.right[node]) if c >= 0]
        if not kids:
            break
        err = objective(tree.samples[tree.point[kids]])
        n_evals += len(kids)
        i = 0 if len(kids) == 1 or err[0] < err[1] else 1
        node = kids[i]
        if err[i] < best_err:
            best_err, best = float(err[i]), int(tree.point[node])
    return best, best_err, n_evals


def _reference_kd_beam(tree: MedianKDTree, objective, beam: int) -> tuple[int, float, int]:
    """The kd descent keeping the ``beam`` best children of a level (heapq.nsmallest over each
    node's right child, then its left one), one query at a time."""
    frontier, best_err = [0], float(objective(tree.samples[tree.point[:1]])[0])
    best, n_evals = int(tree.point[0]), 1
    while frontier:
        kids = [int(c) for n in frontier for c in (tree.right[n], tree.left[n]) if c >= 0]
        if not kids:
            break
        err = objective(tree.samples[tree.point[kids]])
        n_evals += len(kids)
        i = int(np.argmin(err))
        if err[i] < best_err:
            best_err, best = float(err[i]), int(tree.point[kids[i]])
        frontier = [kids[i] for i in heapq.nsmallest(beam, range(len(kids)), key=err.__getitem__)]
    return best, best_err, n_evals


def test_constraint_stack_equals_one_query_at_a_time(prim, setup):
    S, last, hand, pose, joints, queries = setup
    lh, rh = (cmu_joint_map().index(prim.skeleton, k) for k in ("left_hip", "right_hip"))
    joints = sorted(set(joints) | {lh, rh})
    pos, rot = prim.key_frame_pose(S[:50], [last], joints)
    rng = np.random.default_rng(0)
    masked = [
        [
            Constraint("position", last, (hand,), rng.normal(size=(1, 3)), mask=np.array([1.0, 0.0, 1.0])),
            Constraint("heading", last, (lh, rh), np.array([1.0, 0.0, rng.normal()])),
        ]
        for _ in range(6)
    ]
    mixed = [
        [Constraint("position", last, (hand,), rng.normal(size=(1, 3)), mask=m)]
        for m in ([1.0, 1.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 0.0])
    ]  # masks differ between queries
    for qs in [[[c] for c in queries[k]] for k in KINDS] + [masked, mixed]:
        stack = ConstraintStack(qs)
        query = rng.integers(0, len(qs), size=len(pos))
        got = stack.errors(pos, rot, [last], joints, query)
        want = np.stack(
            [constraint_errors(qs[q], pos[b : b + 1], rot[b : b + 1], [last], joints)[0] for b, q in enumerate(query)]
        )
        assert np.array_equal(got, want)  # bit for bit, not approximately
    with pytest.raises(ValueError, match="same kinds, frames and joints"):
        ConstraintStack([[queries["position"][0]], [queries["orientation"][0]]])


def test_index_objective_equals_objective_and_brute_force(prim, setup):
    S, last, _, _, joints, queries = setup
    index = KeyFramePositionIndex(prim, S, [last], joints)
    rows = np.array([5, 3, 699, 0, 3])
    for kind in KINDS:
        qs = queries[kind]
        f = index.objective_many(ConstraintStack([[c] for c in qs]))
        for q, c in enumerate(qs[:4]):
            assert np.array_equal(f(np.full(len(rows), q), rows), Objective(prim, [c])(S[rows]))
            exact, brute = index.search([c]), brute_force(S, Objective(prim, [c]))
            assert (exact.index, exact.error) == (brute.index, brute.error)
    with pytest.raises(ValueError, match="not precomputed"):
        index.objective_many(ConstraintStack([[Constraint("position", 0, (joints[0],), np.zeros((1, 3)))]]))


@pytest.mark.parametrize("kind", ["kmeans", "gmm", "median"])
def test_lockstep_tree_search_equals_one_query_at_a_time(prim, setup, kind):
    S, last, _, _, joints, queries = setup
    tree = SpacePartitioningTree(S, kind, leaf_size=8, seed=0)
    index = KeyFramePositionIndex(prim, tree.points, [last], joints)
    for ckind in KINDS:
        qs = queries[ckind]
        evaluate = index.objective_many(ConstraintStack([[c] for c in qs]))
        for beam in (1, 2, 3, tree.n_nodes):
            many = tree.search_many(evaluate, len(qs), beam)
            for c, r in zip(qs, many):
                obj = Objective(prim, [c])
                one = tree.search(obj, beam)
                assert (
                    (r.index, r.error, r.n_evals)
                    == (one.index, one.error, one.n_evals)
                    == _reference_beam(tree, Objective(prim, [c]), beam)
                )
                assert one.n_evals == obj.n_evals and np.array_equal(r.latent, S[r.index])


def test_lockstep_kd_search_equals_one_query_at_a_time(prim, setup):
    S, last, _, _, joints, queries = setup
    tree = MedianKDTree(S)
    index = KeyFramePositionIndex(prim, S, [last], joints)
    for ckind in KINDS:
        qs = queries[ckind]
        many = tree.search_many(index.objective_many(ConstraintStack([[c] for c in qs])), len(qs))
        for c, r in zip(qs, many):
            obj = Objective(prim, [c])
            one = tree.search(obj)
            assert (
                (r.index, r.error, r.n_evals)
                == (one.index, one.error, one.n_evals)
                == _reference_greedy(tree, Objective(prim, [c]))
            )
            assert one.n_evals == obj.n_evals


@pytest.mark.parametrize("beam", [2, 3])
def test_lockstep_kd_beam_search_equals_one_query_at_a_time(prim, setup, beam):
    """The kd-tree with a beam (Fig. 4.12's median tree at the k-means tree's evaluations): the
    lockstep search gives each query what the per-query reference gives; a beam as wide as the
    tree visits every sample (brute force)."""
    S, last, _, _, joints, queries = setup
    tree = MedianKDTree(S)
    index = KeyFramePositionIndex(prim, S, [last], joints)
    for ckind in KINDS:
        qs = queries[ckind]
        many = tree.search_many(index.objective_many(ConstraintStack([[c] for c in qs])), len(qs), beam)
        for c, r in zip(qs, many):
            obj = Objective(prim, [c])
            one = tree.search(obj, beam)
            assert (r.index, r.error, r.n_evals) == (one.index, one.error, one.n_evals)
            assert (r.index, r.error, r.n_evals) == _reference_kd_beam(tree, Objective(prim, [c]), beam)
            assert one.n_evals == obj.n_evals <= 1 + 2 * beam * tree.depth
    c = queries["position"][0]
    wide = tree.search(Objective(prim, [c]), tree.n_nodes)
    assert wide.n_evals == len(S) and wide.index == brute_force(S, Objective(prim, [c])).index
    with pytest.raises(ValueError, match="beam"):
        tree.search(Objective(prim, [c]), 0)


@pytest.mark.parametrize("beam", [1, 2, 4])
def test_lockstep_searches_break_ties_as_the_reference(beam):
    """Objective values rounded to a coarse grid (many ties): the first of equal values wins,
    in the beam and among leaf samples, as heapq.nsmallest and argmin did."""
    rng = np.random.default_rng(1)
    S = rng.normal(size=(400, 3))
    targets = rng.normal(size=(9, 3))

    def evaluate(query, rows, points):
        return np.round(np.linalg.norm(points[rows] - targets[query], axis=1) * 2.0)

    tree = SpacePartitioningTree(S, "kmeans", leaf_size=6, seed=0)
    many = tree.search_many(lambda q, r: evaluate(q, r, tree.points), len(targets), beam)
    kd = MedianKDTree(S, "cyclic")
    kd_many = kd.search_many(lambda q, r: evaluate(q, r, S), len(targets))
    kd_beam = kd.search_many(lambda q, r: evaluate(q, r, S), len(targets), beam)
    kd_general = kd._beam_search(lambda q, r: evaluate(q, r, S), len(targets), 1)  # beam 1 by the beam code
    for q, (r, k, kb, kg) in enumerate(zip(many, kd_many, kd_beam, kd_general)):

        def objective(X, q=q):
            return np.round(np.linalg.norm(X - targets[q], axis=1) * 2.0)

        assert (r.index, r.error, r.n_evals) == _reference_beam(tree, objective, beam)
        assert (k.index, k.error, k.n_evals) == _reference_greedy(kd, objective) == (kg.index, kg.error, kg.n_evals)
        assert (kb.index, kb.error, kb.n_evals) == _reference_kd_beam(kd, objective, beam)


def test_random_search_many_equals_random_search(prim, setup):
    _, _, _, _, _, queries = setup
    for kind in KINDS:
        qs = queries[kind]
        rng = np.random.default_rng(11)
        one = [random_search(prim, Objective(prim, [c]), 30, rng) for c in qs]
        many = random_search_many(prim, [[c] for c in qs], 30, np.random.default_rng(11))
        for a, b in zip(one, many):
            assert (a.index, a.error, a.n_evals) == (b.index, b.error, b.n_evals)
            assert np.array_equal(a.latent, b.latent)


def test_gmm_log_density_equals_score_samples(prim):
    g = prim.gmm_
    for n in (1, 2, 17, 400):
        X = prim.sample(n, n) * 1.5
        assert np.array_equal(gmm_log_density(g, X), g.score_samples(X))
        wide = np.concatenate([X, X], axis=1)[:, prim.n_latent :]  # a strided view, as StepChain.split gives
        assert np.array_equal(gmm_log_density(g, wide), g.score_samples(wide))
    assert np.array_equal(prim.log_prob(g.means_), g.score_samples(g.means_))
    with pytest.raises(ValueError, match="NaN or infinity"):
        prim.log_prob(np.full((1, prim.n_latent), np.nan))
