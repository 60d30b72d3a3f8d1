"""Space-partitioning trees over latent samples of a motion primitive (Du 2022 Sec. 4.4.2,
4.5.2, 4.6.2; Herrmann et al. 2017).

The GMM of a primitive is discretised into a dense sample set (10,000 latent vectors in
the thesis) and a tree is built over it:

- k-means tree: "we apply the k-means algorithm recursively on the latent space", four
  children per node (Fig. 4.7);
- GMM tree: a 4-component Gaussian mixture clusters the samples at every node;
- median tree: "splits the data according to the median of the dimension with the
  maximum variance" (two children).

:class:`SpacePartitioningTree` represents inner nodes by the mean latent vector of their
samples; leaves hold the samples. Its search (Sec. 4.5.2) descends level by level,
evaluating the objective of Eq. 4.2 on the means of the children of the current
candidates and keeping the best ``beam`` of them (DFKI's code default keeps 4,
``n_cluster_search_candidates`` in ``motion_generator/algorithm_configuration.py``; the n
best are taken with ``heapq.nsmallest``, not ``heap[:n]``, the known bug of DFKI's code); at
leaves the samples themselves are evaluated. Evaluations are O(l k c) instead of O(N) (levels,
children, candidates). With ``kind="median"`` this is *our* median-split tree (node means
and the same beam as the k-means tree).

:class:`MedianKDTree` is the median tree of Fig. 4.12 modelled on DFKI's kd-tree
(``space_partitioning/kdtree.py`` of the morphablegraphs code, which DFKI's code uses in
the leaves of its k-means tree, ``cluster_tree_node_builder.py``): every node *is* a
sample, the median sample along the split dimension (the thesis' dimension of maximum
variance; DFKI's kd-tree cycles the dimensions by depth, ``split="cyclic"``), and a greedy
descent that evaluates both children of the current node and moves to the better one,
returning the best sample evaluated on the way (about 2 log2 N evaluations); with a
``beam`` > 1 (our option, to give it the k-means tree's evaluation count) the best
``beam`` children of a level are kept. :func:`select_beam` picks a beam from an evaluation
budget (the thesis' "less than 120 evaluations").

References (Fig. 4.12): :func:`random_search` (the best of 100 fresh GMM samples) and
:func:`brute_force` (all samples of the tree). :class:`KeyFramePositionIndex` is our
"better than the paper" option: the constrained joints' key-frame positions of all
samples are computed once, so that an exact brute-force search costs one vectorised
distance computation per query (no back-projection, no forward kinematics).

Many queries at once (the thousands of random queries of Fig. 4.12): ``search_many`` of
both trees runs the queries in lockstep, evaluating the candidates of all queries at a
level in one call of a batch objective ``evaluate(query, rows)`` (e.g.
:meth:`KeyFramePositionIndex.objective_many` over the precomputed key-frame poses of the
tree's ``points``), and :func:`random_search_many` draws and evaluates the random
references of all queries together. Every query gets exactly what its own search gives
(the same candidates, sample, error and number of evaluations); ``search`` is
``search_many`` with one query.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from threadpoolctl import threadpool_limits

from .constraints import Constraint, ConstraintStack, Objective, kind_error, reference_axes
from .primitive import MotionPrimitive

TREE_KINDS = ("kmeans", "gmm", "median")
# the objective of many queries at once: (query (B,), rows (B,)) -> (B,) values of query[b] at rows[b]
BatchObjective = Callable[[np.ndarray, np.ndarray], np.ndarray]
KD_SPLITS = ("max_variance", "cyclic")


@dataclass
class SearchResult:
    """Best sample found: its index into the tree's samples (or -1 for a fresh sample),
    the latent vector, its objective value and how many latent vectors were evaluated."""

    index: int
    latent: np.ndarray
    error: float
    n_evals: int


def _split_kmeans(X: np.ndarray, k: int, seed: int) -> np.ndarray:
    from sklearn.cluster import KMeans

    return KMeans(n_clusters=k, n_init=1, random_state=seed).fit_predict(X)


def _split_gmm(X: np.ndarray, k: int, seed: int) -> np.ndarray:
    from sklearn.exceptions import ConvergenceWarning
    from sklearn.mixture import GaussianMixture

    reg = 1e-3 * float(np.mean(np.var(X, axis=0))) + 1e-9
    gmm = GaussianMixture(k, covariance_type="full", reg_covar=reg, random_state=seed, max_iter=50)
    with warnings.catch_warnings():  # small nodes: EM may stop before its tolerance; the split is still used
        warnings.simplefilter("ignore", ConvergenceWarning)
        return gmm.fit(X).predict(X)


def _split_median(X: np.ndarray, k: int, seed: int) -> np.ndarray:
    d = int(np.argmax(np.var(X, axis=0)))
    order = np.argsort(X[:, d], kind="stable")
    labels = np.empty(len(X), dtype=np.int64)
    labels[order] = np.arange(len(X)) >= len(X) // 2  # the lower half and the upper half
    return labels


_SPLITTERS: dict[str, tuple[Callable[[np.ndarray, int, int], np.ndarray], int]] = {
    "kmeans": (_split_kmeans, 4),
    "gmm": (_split_gmm, 4),
    "median": (_split_median, 2),
}


class SpacePartitioningTree:
    """A tree over latent samples (module docstring).

    Args:
        samples: (N, d) latent vectors (e.g. 10,000 draws of the primitive's GMM).
        kind: kmeans | gmm | median.
        n_children: children per node (default 4 for k-means and GMM, 2 for median).
        leaf_size: a node with at most this many samples is a leaf.
        seed: random state of the clusterings.

    Attributes: ``means`` (M, d) node means, ``children`` (list of child index arrays),
    ``leaves`` (node -> sample indices), ``depth``, ``points`` (N + M, d): the latent
    vectors a search evaluates, the samples then the node means (node k is row N + k).
    Building runs the clusterings single-threaded (threadpoolctl): on a loaded machine
    BLAS/OpenMP threads made the many small clusterings 10-30x slower.
    """

    def __init__(
        self,
        samples: np.ndarray,
        kind: str = "kmeans",
        n_children: int | None = None,
        leaf_size: int = 16,
        seed: int = 0,
    ) -> None:
        if kind not in TREE_KINDS:
            raise ValueError(f"tree kind must be one of {TREE_KINDS}; got {kind!r}")
        X = np.asarray(samples, dtype=float)
        if X.ndim != 2 or len(X) < 1 or not np.all(np.isfinite(X)):
            raise ValueError(f"tree samples must be a finite (N, d) array with N >= 1; got shape {X.shape}")
        split, default_k = _SPLITTERS[kind]
        k = int(n_children or default_k)
        if k < 2 or int(leaf_size) < 1:
            raise ValueError(f"tree: n_children must be >= 2 and leaf_size >= 1; got {k}, {leaf_size}")
        self.kind, self.samples, self.n_children, self.leaf_size = kind, X, k, int(leaf_size)
        self._padded: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None  # see _tables
        with threadpool_limits(1):  # hundreds of small clusterings: threads only add overhead
            self._build(X, split, k, seed)

    def _build(self, X: np.ndarray, split, k: int, seed: int) -> None:
        means: list[np.ndarray] = []
        self.children: list[np.ndarray] = []
        self.leaves: dict[int, np.ndarray] = {}
        depth = {0: 0}
        stack = [(np.arange(len(X)), 0)]
        means.append(X.mean(axis=0))
        self.children.append(np.zeros(0, dtype=np.int64))
        while stack:
            idx, node = stack.pop()
            labels = split(X[idx], k, seed) if len(idx) > self.leaf_size else None
            groups = [] if labels is None else [idx[labels == c] for c in range(k)]
            groups = [g for g in groups if len(g)]
            if len(groups) < 2:
                self.leaves[node] = idx
                continue
            kids = []
            for g in groups:
                child = len(means)
                means.append(X[g].mean(axis=0))
                self.children.append(np.zeros(0, dtype=np.int64))
                depth[child] = depth[node] + 1
                kids.append(child)
                stack.append((g, child))
            self.children[node] = np.array(kids, dtype=np.int64)
        self.means = np.stack(means)
        self.depth = max(depth.values())
        self.points = np.concatenate([X, self.means])  # the rows of search_many: samples, then node means

    @property
    def n_nodes(self) -> int:
        return len(self.means)

    def search(self, objective: Callable[[np.ndarray], np.ndarray], beam: int = 2) -> SearchResult:
        """Beam descent (module docstring): keep the ``beam`` best children per level,
        evaluate the samples of the leaves reached. ``objective`` maps (B, d) -> (B,)."""
        return self.search_many(lambda query, rows: objective(self.points[rows]), 1, beam)[0]

    def search_many(self, evaluate: BatchObjective, n_queries: int, beam: int = 2) -> list[SearchResult]:
        """:meth:`search` for ``n_queries`` queries in lockstep (Sec. 4.5.2): level by level,
        the candidates of all queries (the samples of the leaves in their beams, then the
        children of their inner nodes) are evaluated in one call ``evaluate(query, rows)``
        -> (B,), the objective of query ``query[b]`` at row ``rows[b]`` of ``points``
        (e.g. :meth:`KeyFramePositionIndex.objective_many`). Every query gets what
        :meth:`search` gives it alone: the same candidates in the same order, the same
        number of evaluations, ties broken alike (the first of equal values; NaN last)."""
        if int(beam) < 1:
            raise ValueError(f"tree search: beam must be >= 1; got {beam}")
        kids_of, samples_of, is_leaf = self._tables()
        q_all = np.arange(int(n_queries))
        frontier = np.zeros((len(q_all), 1), dtype=np.int64)  # node ids of each query's beam, -1: none
        best_err, best = np.full(len(q_all), np.inf), np.full(len(q_all), -1, dtype=np.int64)
        n_evals = np.zeros(len(q_all), dtype=np.int64)
        while (frontier >= 0).any():
            live = frontier >= 0
            node = np.where(live, frontier, 0)
            leaf = live & is_leaf[node]
            # the samples of the leaves reached, in beam order; then the children of the inner nodes
            cand = np.where(leaf[..., None], samples_of[node], -1).reshape(len(q_all), -1)
            err = _evaluate_padded(evaluate, cand)
            n_evals += (cand >= 0).sum(axis=1)
            i = np.argmin(err, axis=1)
            better = err[q_all, i] < best_err
            best_err[better], best[better] = err[better, i[better]], cand[better, i[better]]
            kids = np.where((live & ~leaf)[..., None], kids_of[node], -1).reshape(len(q_all), -1)
            err = _evaluate_padded(evaluate, kids, offset=len(self.samples))
            n_evals += (kids >= 0).sum(axis=1)
            order = np.lexsort((err, kids < 0), axis=-1)[:, : int(beam)]  # stable: as heapq.nsmallest
            frontier = np.take_along_axis(kids, order, axis=1)
        return _results(self.samples, best, best_err, n_evals)

    def _tables(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Padded arrays of the tree (-1: none): children per node (M, max children), samples
        per leaf (M, max leaf size), and whether a node is a leaf (M,); built once."""
        if self._padded is None:
            kids = np.full((self.n_nodes, max(len(c) for c in self.children)), -1, dtype=np.int64)
            leaf_samples = np.full((self.n_nodes, max(len(v) for v in self.leaves.values())), -1, dtype=np.int64)
            for n, c in enumerate(self.children):
                kids[n, : len(c)] = c
            for n, idx in self.leaves.items():
                leaf_samples[n, : len(idx)] = idx
            is_leaf = np.zeros(self.n_nodes, dtype=bool)
            is_leaf[list(self.leaves)] = True
            self._padded = (kids, leaf_samples, is_leaf)
        return self._padded


class MedianKDTree:
    """A kd-tree over latent samples modelled on DFKI's (module docstring): every node is the
    median sample of its subset along the split dimension, the samples below it form the left
    subtree, those above it the right one.

    Args:
        samples: (N, d) latent vectors.
        split: ``max_variance`` (the thesis: "the median of the dimension with the maximum
            variance", of the node's samples) or ``cyclic`` (DFKI's code: dimension depth mod d).

    Attributes: ``point`` (node -> sample index), ``left`` / ``right`` (node -> child node,
    -1 for none), ``axis`` (split dimension, -1 at leaves), ``depth``.
    """

    def __init__(self, samples: np.ndarray, split: str = "max_variance") -> None:
        if split not in KD_SPLITS:
            raise ValueError(f"kd-tree split must be one of {KD_SPLITS}; got {split!r}")
        X = np.asarray(samples, dtype=float)
        if X.ndim != 2 or len(X) < 1 or not np.all(np.isfinite(X)):
            raise ValueError(f"tree samples must be a finite (N, d) array with N >= 1; got shape {X.shape}")
        self.samples, self.split, self.kind = X, split, "median_kd"
        n = len(X)
        self.point = np.full(n, -1, dtype=np.int64)
        self.left = np.full(n, -1, dtype=np.int64)
        self.right = np.full(n, -1, dtype=np.int64)
        self.axis = np.full(n, -1, dtype=np.int64)
        node_depth = np.zeros(n, dtype=np.int64)
        stack, n_nodes = [(np.arange(n), 0)], 1  # (samples of the node, node id); every node takes one sample
        while stack:
            idx, node = stack.pop()
            if len(idx) == 1:
                self.point[node] = idx[0]
                continue
            depth = node_depth[node]
            ax = int(np.argmax(np.var(X[idx], axis=0))) if split == "max_variance" else int(depth % X.shape[1])
            order = idx[np.argsort(X[idx, ax], kind="stable")]
            m = len(order) // 2
            self.point[node], self.axis[node] = order[m], ax
            for side, part in ((self.left, order[:m]), (self.right, order[m + 1 :])):
                if len(part):
                    side[node] = n_nodes
                    node_depth[n_nodes] = depth + 1
                    stack.append((part, n_nodes))
                    n_nodes += 1
        self.depth = int(node_depth.max())

    @property
    def n_nodes(self) -> int:
        return len(self.point)

    @property
    def points(self) -> np.ndarray:
        """The latent vectors a search evaluates (the rows of :meth:`search_many`): the samples."""
        return self.samples

    def search(self, objective: Callable[[np.ndarray], np.ndarray], beam: int = 1) -> SearchResult:
        """Greedy descent (DFKI's ``find_best_example``): evaluate the root's sample, then
        at every node the samples of its children, moving to the child with the lower
        objective (the right one on a tie, as DFKI); the best sample evaluated wins. With
        ``beam`` > 1 (our option) the best ``beam`` children of all nodes kept at a level
        are kept for the next one."""
        return self.search_many(lambda query, rows: objective(self.samples[rows]), 1, beam)[0]

    def search_many(self, evaluate: BatchObjective, n_queries: int, beam: int = 1) -> list[SearchResult]:
        """:meth:`search` for ``n_queries`` queries in lockstep: at every level the children of
        all queries' current nodes are evaluated in one call ``evaluate(query, rows)`` -> (B,)
        (rows: sample indices; :meth:`SpacePartitioningTree.search_many`); every query gets
        what :meth:`search` gives it alone."""
        if int(beam) < 1:
            raise ValueError(f"kd-tree search: beam must be >= 1; got {beam}")
        if int(beam) > 1:
            return self._beam_search(evaluate, int(n_queries), int(beam))
        q_all = np.arange(int(n_queries))
        node = np.zeros(len(q_all), dtype=np.int64)
        best = np.full(len(q_all), self.point[0], dtype=np.int64)
        best_err = np.array(evaluate(q_all, best), dtype=float)
        n_evals = np.ones(len(q_all), dtype=np.int64)
        active = np.ones(len(q_all), dtype=bool)
        while active.any():
            kids = np.where(active[:, None], np.stack([self.left[node], self.right[node]], axis=1), -1)
            has = kids >= 0
            err = _evaluate_padded(evaluate, np.where(has, self.point[np.maximum(kids, 0)], -1))
            n_evals += has.sum(axis=1)
            # one child: that one; two: the right one unless the left is lower
            side = np.where(has[:, 1] & ~(has[:, 0] & (err[:, 0] < err[:, 1])), 1, 0)
            active = has.any(axis=1)
            node = np.where(active, kids[q_all, side], node)
            better = active & (err[q_all, side] < best_err)
            best_err[better], best[better] = err[better, side[better]], self.point[node[better]]
        return _results(self.samples, best, best_err, n_evals)

    def _beam_search(self, evaluate: BatchObjective, n_queries: int, beam: int) -> list[SearchResult]:
        """:meth:`search_many` keeping the best ``beam`` children per level (each node's right
        child before its left one, so that ties go right as in the greedy descent); the best
        sample evaluated wins."""
        q_all = np.arange(n_queries)
        frontier = np.zeros((n_queries, 1), dtype=np.int64)  # node ids of each query's beam, -1: none
        best = np.full(n_queries, self.point[0], dtype=np.int64)
        best_err = np.array(evaluate(q_all, best), dtype=float)
        n_evals = np.ones(n_queries, dtype=np.int64)
        while (frontier >= 0).any():
            live = frontier >= 0
            node = np.where(live, frontier, 0)
            kids = np.where(live[..., None], np.stack([self.right[node], self.left[node]], axis=-1), -1)
            kids = kids.reshape(n_queries, -1)
            err = _evaluate_padded(evaluate, np.where(kids >= 0, self.point[np.maximum(kids, 0)], -1))
            n_evals += (kids >= 0).sum(axis=1)
            i = np.argmin(err, axis=1)
            better = err[q_all, i] < best_err
            best_err[better], best[better] = err[better, i[better]], self.point[kids[better, i[better]]]
            order = np.lexsort((err, kids < 0), axis=-1)[:, :beam]
            frontier = np.take_along_axis(kids, order, axis=1)
        return _results(self.samples, best, best_err, n_evals)


def select_beam(mean_evals: dict[int, float], budget: float) -> tuple[int, bool]:
    """The k-means tree's beam from an evaluation budget: the largest beam whose mean number
    of evaluations per query is below ``budget`` (the thesis: "less than 120 evaluations").
    Returns (beam, within budget); when no beam fits, the smallest one and False."""
    if not mean_evals:
        raise ValueError("select_beam: no beams measured")
    fits = [b for b, e in mean_evals.items() if e < budget]
    return (max(fits), True) if fits else (min(mean_evals), False)


def _results(samples: np.ndarray, best: np.ndarray, errors: np.ndarray, n_evals: np.ndarray) -> list[SearchResult]:
    """One SearchResult per query from the arrays of a lockstep search."""
    return [SearchResult(int(b), samples[b].copy(), float(e), int(n)) for b, e, n in zip(best, errors, n_evals)]


def _evaluate_padded(evaluate: BatchObjective, cand: np.ndarray, offset: int = 0) -> np.ndarray:
    """(Q, C) objective values of the candidates ``cand`` (Q, C) of Q queries (rows, -1:
    none, inf there) by one call ``evaluate(query, rows + offset)`` over the real ones,
    query by query in column order."""
    err = np.full(cand.shape, np.inf)
    q, c = np.nonzero(cand >= 0)
    if len(q):
        err[q, c] = evaluate(q, cand[q, c] + offset)
    return err


def brute_force(samples: np.ndarray, objective: Callable[[np.ndarray], np.ndarray], batch: int = 2500) -> SearchResult:
    """Exact best of all ``samples`` (the ground truth of Fig. 4.12), in batches."""
    errs = np.concatenate([objective(samples[i : i + batch]) for i in range(0, len(samples), batch)])
    i = int(np.argmin(errs))
    return SearchResult(i, samples[i].copy(), float(errs[i]), len(samples))


def random_search(
    primitive: MotionPrimitive,
    objective: Callable[[np.ndarray], np.ndarray],
    n: int = 100,
    rng: np.random.Generator | int | None = None,
) -> SearchResult:
    """The best of ``n`` fresh samples of the primitive's GMM ("100 random samples are
    used in parallel", Sec. 4.6.2)."""
    S = primitive.sample(n, rng)
    errs = objective(S)
    i = int(np.argmin(errs))
    return SearchResult(-1, S[i].copy(), float(errs[i]), n)


def random_search_many(
    primitive: MotionPrimitive,
    queries: Sequence[Sequence[Constraint]],
    n: int = 100,
    rng: np.random.Generator | int | None = None,
) -> list[SearchResult]:
    """:func:`random_search` for many queries of the same structure (:class:`ConstraintStack`):
    ``n`` fresh GMM samples per query, drawn from ``rng`` query by query as one
    :func:`random_search` per query draws them, their key-frame poses computed in batches and
    all queries' objectives in one call; each result is that query's :func:`random_search`."""
    rng = np.random.default_rng(rng)
    stack = ConstraintStack(queries)
    fresh = np.concatenate([primitive.sample(n, rng) for _ in range(stack.n_queries)])  # (Q n, d), query-major
    index = KeyFramePositionIndex(
        primitive, fresh, sorted({c.frame for c in stack.slots}), sorted({j for c in stack.slots for j in c.joints})
    )
    rows = np.arange(len(fresh))
    err = index.objective_many(stack)(rows // n, rows).reshape(stack.n_queries, n)
    best = np.argmin(err, axis=1)
    return [SearchResult(-1, fresh[q * n + i].copy(), float(err[q, i]), n) for q, i in enumerate(best)]


class KeyFramePositionIndex:
    """Eq. 4.2 over precomputed key-frame poses (our option, not in the paper).

    The global positions and rotations of ``joints`` at canonical ``frames`` (f_k(M(s)) of
    Eq. 4.2) are computed once for all ``samples``, in batches; a query whose constraints
    use only those frames and joints then costs no back-projection and no FK:

    - :meth:`search`: exact brute force, one vectorised error computation; the same
      answer as :func:`brute_force`;
    - :meth:`objective_many`: the objectives of many queries at rows of ``samples``, the
      values :class:`~.constraints.Objective` gives on those latent vectors (FK is
      elementwise over a batch), for the lockstep tree searches over a tree's ``points``
      (:meth:`SpacePartitioningTree.search_many`, :meth:`MedianKDTree.search_many`).
    """

    def __init__(
        self,
        primitive: MotionPrimitive,
        samples: np.ndarray,
        frames: Sequence[int],
        joints: Sequence[int],
        batch: int = 2500,
    ) -> None:
        self.samples = np.asarray(samples, dtype=float)
        self.frames, self.joints = [int(f) for f in frames], [int(j) for j in joints]
        parts = [
            primitive.key_frame_pose(self.samples[i : i + batch], self.frames, self.joints)
            for i in range(0, len(self.samples), batch)
        ]
        self.positions = np.concatenate([p for p, _ in parts])  # (N, F, J', 3)
        self.rotations = np.concatenate([r for _, r in parts])
        self._inputs: dict[tuple, tuple[np.ndarray | None, np.ndarray | None]] = {}

    def _error_inputs(self, c: Constraint) -> tuple[np.ndarray | None, np.ndarray | None]:
        """What the error of ``c`` reads for all samples, gathered once per kind, frame and
        joints: positions (N, J', 3) or, for orientation, the reference axes (N, 3, 3)."""
        key = (c.kind, c.frame, c.joints)
        if key not in self._inputs:
            try:
                f, idx = self.frames.index(c.frame), [self.joints.index(j) for j in c.joints]
            except ValueError:
                raise ValueError(
                    f"KeyFramePositionIndex: constraint on frame {c.frame}, joints {c.joints} not "
                    f"precomputed (frames {self.frames}, joints {self.joints})"
                ) from None
            orient = c.kind == "orientation"
            self._inputs[key] = (
                (None, reference_axes(self.rotations[:, f, idx])) if orient else (self.positions[:, f, idx], None)
            )
        return self._inputs[key]

    def errors(self, constraints: Sequence[Constraint]) -> np.ndarray:
        """(N, n_c) per-constraint errors of all samples (Eq. 4.2's terms)."""
        out = np.empty((len(self.samples), len(constraints)))
        for k, c in enumerate(constraints):  # the (few) constraints; all samples at once
            pos, axes = self._error_inputs(c)
            out[:, k] = kind_error(c.kind, pos, None, c.target, c.active_mask, axes=axes)
        return out

    def objective_many(self, stack: ConstraintStack) -> BatchObjective:
        """O(s, c) of Eq. 4.2 for the queries of ``stack``: ``f(query, rows)`` -> (B,), query
        ``query[b]`` at sample ``rows[b]``."""

        def f(query: np.ndarray, rows: np.ndarray) -> np.ndarray:
            return stack.errors(self.positions[rows], self.rotations[rows], self.frames, self.joints, query).sum(axis=1)

        try:
            f(np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64))  # checks the frames and joints once
        except ValueError as exc:
            raise ValueError(f"KeyFramePositionIndex: {exc}") from None
        return f

    def search(self, constraints: Sequence[Constraint]) -> SearchResult:
        """The exact best sample for ``constraints`` (brute force on the precomputed poses)."""
        total = self.errors(constraints).sum(axis=1)
        i = int(np.argmin(total))
        return SearchResult(i, self.samples[i].copy(), float(total[i]), 0)


def tree_search(
    tree: SpacePartitioningTree, primitive: MotionPrimitive, constraints: Sequence[Constraint], beam: int = 2
) -> SearchResult:
    """Convenience: tree search with the Eq. 4.2 objective of ``constraints``."""
    return tree.search(Objective(primitive, constraints), beam)
