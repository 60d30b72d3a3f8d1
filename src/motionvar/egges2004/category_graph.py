"""Category transition graph (Egges et al. 2004, Sec. 5.3, Fig. 3; shortest paths of
Sec. 7.1).

Nodes are resting-posture categories; P(c1 => c2) is estimated by counting the
transitions between consecutive resting segments in the recordings; T_c,min and T_c,max
are the shortest and longest stays in category c.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from scipy.sparse.csgraph import shortest_path


@dataclass(frozen=True)
class CategoryGraph:
    """P(c1 => c2) as a row-stochastic matrix (rows without data are all zero), the
    transition counts, and T_min / T_max per category in seconds (NaN without data)."""

    names: tuple[str, ...]
    counts: np.ndarray
    probabilities: np.ndarray
    t_min: np.ndarray
    t_max: np.ndarray

    @classmethod
    def from_sequences(
        cls,
        names: Sequence[str],
        sequences: Sequence[Sequence[int]],
        stays: Sequence[Sequence[float]],
    ) -> "CategoryGraph":
        """From, per recording, the category index of each resting segment in time order
        (``sequences``) and how long each stay lasted in seconds (``stays``, same shape;
        NaN for a stay whose length is unknown, e.g. cut by the recording's end)."""
        k = len(names)
        counts = np.zeros((k, k), dtype=np.int64)
        durations: list[list[float]] = [[] for _ in range(k)]
        for seq, dur in zip(sequences, stays, strict=True):
            seq = np.asarray(seq, dtype=np.int64)
            if len(seq) != len(dur):
                raise ValueError("CategoryGraph: each sequence needs one stay duration per segment")
            if len(seq) and (seq.min() < 0 or seq.max() >= k):
                raise ValueError(f"CategoryGraph: category index out of range [0, {k})")
            np.add.at(counts, (seq[:-1], seq[1:]), 1)
            for c, d in zip(seq, dur):
                if not np.isnan(d):
                    durations[c].append(float(d))
        rows = counts.sum(axis=1, keepdims=True)
        prob = np.divide(counts, rows, out=np.zeros((k, k)), where=rows > 0)
        t_min = np.array([min(d) if d else np.nan for d in durations])
        t_max = np.array([max(d) if d else np.nan for d in durations])
        return cls(tuple(names), counts, prob, t_min, t_max)

    @property
    def n(self) -> int:
        return len(self.names)

    def hops(self) -> np.ndarray:
        """(k, k) number of transitions on the shortest path between categories (inf if
        unreachable), along edges with P > 0."""
        return shortest_path((self.probabilities > 0).astype(float), directed=True, unweighted=True)

    def routable_pairs(self) -> np.ndarray:
        """(m, 2) (start, end) category pairs that :meth:`shortest_route` can join: at
        least one transition out of start, then a path to end (a subject whose recordings
        never go from one category to another has no such path)."""
        first_step = (self.probabilities > 0).astype(int)
        then_reach = np.isfinite(self.hops()).astype(int)
        return np.argwhere(first_step @ then_reach > 0)

    def shortest_route(self, start: int, end: int, rng: np.random.Generator) -> list[int]:
        """Categories on a shortest path from ``start`` to ``end`` (both included); the
        shortest cycle when ``start == end`` (Sec. 7.1). Ties are broken at random."""
        adj = self.probabilities > 0
        hops = self.hops()
        first = np.flatnonzero(adj[start])
        if first.size == 0:
            raise ValueError(f"category {self.names[start]!r} has no outgoing transition in the data")
        to_end = hops[first, end]  # hops[end, end] = 0: a self-loop is a cycle of one
        best = to_end.min()
        if not np.isfinite(best):
            raise ValueError(f"no path from category {self.names[start]!r} to {self.names[end]!r} in the graph")
        route = [start, int(rng.choice(first[to_end == best]))]
        while route[-1] != end:
            succ = np.flatnonzero(adj[route[-1]])
            left = hops[succ, end]
            route.append(int(rng.choice(succ[left == left.min()])))
        return route
