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
candidates and keeping the best ``beam`` of them (DFKI used 2; the n best are taken with
``heapq.nsmallest``, not ``heap[:n]``, the known bug of DFKI's code); at leaves the
samples themselves are evaluated. Evaluations are O(l k c) instead of O(N) (levels,
children, candidates). With ``kind="median"`` this is *our* median-split tree (node means
and the same beam as the k-means tree).

:class:`MedianKDTree` is the median tree as DFKI built it for the comparison of Fig. 4.12
(``space_partitioning/kdtree.py`` of the morphablegraphs code): a kd-tree whose every node
*is* a sample, the median sample along the split dimension (the thesis' dimension of
maximum variance; DFKI's code cycles the dimensions by depth, ``split="cyclic"``), and a
greedy descent that evaluates both children of the current node and moves to the better
one, returning the best sample evaluated on the way (about 2 log2 N evaluations).
:func:`select_beam` picks the k-means tree's beam from an evaluation budget (the thesis'
"less than 120 evaluations").

References (Fig. 4.12): :func:`random_search` (the best of 100 fresh GMM samples) and
:func:`brute_force` (all samples of the tree). :class:`KeyFramePositionIndex` is our
"better than the paper" option: the constrained joints' key-frame positions of all
samples are computed once, so that an exact brute-force search costs one vectorised
distance computation per query (no back-projection, no forward kinematics).
"""

from __future__ import annotations

import heapq
import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from sklearn.cluster import KMeans
from sklearn.exceptions import ConvergenceWarning
from sklearn.mixture import GaussianMixture
from threadpoolctl import threadpool_limits

from .constraints import Constraint, Objective
from .primitive import MotionPrimitive

TREE_KINDS = ("kmeans", "gmm", "median")
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
    return KMeans(n_clusters=k, n_init=1, random_state=seed).fit_predict(X)


def _split_gmm(X: np.ndarray, k: int, seed: int) -> np.ndarray:
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
    ``leaves`` (node -> sample indices), ``depth``. Building runs the clusterings
    single-threaded (threadpoolctl): on a loaded machine BLAS/OpenMP threads made the
    many small clusterings 10-30x slower.
    """

    def __init__(self, samples: np.ndarray, kind: str = "kmeans", n_children: int | None = None,
                 leaf_size: int = 16, seed: int = 0) -> None:
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

    @property
    def n_nodes(self) -> int:
        return len(self.means)

    def search(self, objective: Callable[[np.ndarray], np.ndarray], beam: int = 2) -> SearchResult:
        """Beam descent (module docstring): keep the ``beam`` best children per level,
        evaluate the samples of the leaves reached. ``objective`` maps (B, d) -> (B,)."""
        if int(beam) < 1:
            raise ValueError(f"tree search: beam must be >= 1; got {beam}")
        frontier, n_evals = [0], 0
        best = (np.inf, -1)
        while frontier:
            leaf_nodes = [n for n in frontier if n in self.leaves]
            inner = [n for n in frontier if n not in self.leaves]
            if leaf_nodes:
                idx = np.concatenate([self.leaves[n] for n in leaf_nodes])
                err = objective(self.samples[idx])
                n_evals += len(idx)
                i = int(np.argmin(err))
                if err[i] < best[0]:
                    best = (float(err[i]), int(idx[i]))
            if not inner:
                break
            kids = np.concatenate([self.children[n] for n in inner])
            err = objective(self.means[kids])
            n_evals += len(kids)
            frontier = [int(kids[i]) for i in heapq.nsmallest(int(beam), range(len(kids)), key=err.__getitem__)]
        return SearchResult(best[1], self.samples[best[1]].copy(), best[0], n_evals)


class MedianKDTree:
    """The DFKI kd-tree over latent samples (module docstring): every node is the median
    sample of its subset along the split dimension, the samples below it form the left
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
            for side, part in ((self.left, order[:m]), (self.right, order[m + 1:])):
                if len(part):
                    side[node] = n_nodes
                    node_depth[n_nodes] = depth + 1
                    stack.append((part, n_nodes))
                    n_nodes += 1
        self.depth = int(node_depth.max())

    @property
    def n_nodes(self) -> int:
        return len(self.point)

    def search(self, objective: Callable[[np.ndarray], np.ndarray]) -> SearchResult:
        """Greedy descent (DFKI's ``find_best_example``): evaluate the root's sample, then
        at every node the samples of its children, moving to the child with the lower
        objective (the right one on a tie, as DFKI); the best sample evaluated wins."""
        node = 0
        best_err = float(objective(self.samples[self.point[:1]])[0])
        best, n_evals = int(self.point[0]), 1
        while True:
            kids = [int(c) for c in (self.left[node], self.right[node]) if c >= 0]
            if not kids:
                break
            err = objective(self.samples[self.point[kids]])
            n_evals += len(kids)
            i = 0 if len(kids) == 1 or err[0] < err[1] else 1
            node = kids[i]
            if err[i] < best_err:
                best_err, best = float(err[i]), int(self.point[node])
        return SearchResult(best, self.samples[best].copy(), best_err, n_evals)


def select_beam(mean_evals: dict[int, float], budget: float) -> tuple[int, bool]:
    """The k-means tree's beam from an evaluation budget: the largest beam whose mean number
    of evaluations per query is below ``budget`` (the thesis: "less than 120 evaluations").
    Returns (beam, within budget); when no beam fits, the smallest one and False."""
    if not mean_evals:
        raise ValueError("select_beam: no beams measured")
    fits = [b for b, e in mean_evals.items() if e < budget]
    return (max(fits), True) if fits else (min(mean_evals), False)


def brute_force(samples: np.ndarray, objective: Callable[[np.ndarray], np.ndarray],
                batch: int = 2500) -> SearchResult:
    """Exact best of all ``samples`` (the ground truth of Fig. 4.12), in batches."""
    errs = np.concatenate([objective(samples[i:i + batch]) for i in range(0, len(samples), batch)])
    i = int(np.argmin(errs))
    return SearchResult(i, samples[i].copy(), float(errs[i]), len(samples))


def random_search(primitive: MotionPrimitive, objective: Callable[[np.ndarray], np.ndarray], n: int = 100,
                  rng: np.random.Generator | int | None = None) -> SearchResult:
    """The best of ``n`` fresh samples of the primitive's GMM ("100 random samples are
    used in parallel", Sec. 4.6.2)."""
    S = primitive.sample(n, rng)
    errs = objective(S)
    i = int(np.argmin(errs))
    return SearchResult(-1, S[i].copy(), float(errs[i]), n)


class KeyFramePositionIndex:
    """Exact search over precomputed key-frame poses (our option, not in the paper).

    The global positions and rotations of ``joints`` at canonical ``frames`` are computed
    once for all samples; a query whose constraints use only those frames and joints is
    then an exact brute force costing one vectorised error computation (no
    back-projection, no FK). Gives the same answer as :func:`brute_force`.
    """

    def __init__(self, primitive: MotionPrimitive, samples: np.ndarray, frames: Sequence[int],
                 joints: Sequence[int], batch: int = 2500) -> None:
        self.samples = np.asarray(samples, dtype=float)
        self.frames, self.joints = [int(f) for f in frames], [int(j) for j in joints]
        parts = [primitive.key_frame_pose(self.samples[i:i + batch], self.frames, self.joints)
                 for i in range(0, len(self.samples), batch)]
        self.positions = np.concatenate([p for p, _ in parts])  # (N, F, J', 3)
        self.rotations = np.concatenate([r for _, r in parts])

    def search(self, constraints: Sequence[Constraint]) -> SearchResult:
        total = np.zeros(len(self.samples))
        for c in constraints:
            try:
                f = self.frames.index(c.frame)
                idx = [self.joints.index(j) for j in c.joints]
            except ValueError:
                raise ValueError(f"KeyFramePositionIndex: constraint on frame {c.frame}, joints {c.joints} "
                                 f"not precomputed (frames {self.frames}, joints {self.joints})") from None
            total += c.error(self.positions[:, f, idx], self.rotations[:, f, idx])
        i = int(np.argmin(total))
        return SearchResult(i, self.samples[i].copy(), float(total[i]), 0)


def tree_search(tree: SpacePartitioningTree, primitive: MotionPrimitive, constraints: Sequence[Constraint],
                beam: int = 2) -> SearchResult:
    """Convenience: tree search with the Eq. 4.2 objective of ``constraints``."""
    return tree.search(Objective(primitive, constraints), beam)
