"""Du 2022 Fig. 4.12 / Sec. 4.6.2: constraint search by the k-means, GMM and median
space-partitioning trees against random sampling and brute force.

Two steps: :func:`search_primitive` runs the random queries on one primitive (one table
row per query, method and beam; rule ``du2022_graph_search``), :func:`evaluate_fig4_12`
summarises the queries of all primitives and measures what the claims of Sec. 4.6.2 are
judged on (:func:`fig4_12_measurements`). Where the thesis says "close" or "most" without a
number, the threshold is declared with the claims (:mod:`motionvar.du2022.claims`)
and written in the claim's note.

Methods (column ``method``):

- ``kmeans``: the k-means tree with beam search, at every beam of ``SearchSettings.candidates``
  (:mod:`~motionvar.du2022.graph.settings`, config ``du2022_graph.search``). Every verdict uses
  the beam fixed in advance, ``beam`` (4, DFKI's code default; column ``selected``); beside
  it the table marks the budget beam (column ``budget_beam``: the largest beam whose mean
  number of evaluations stays under ``max_evaluations``, the thesis' 120), which no verdict uses;
- ``gmm``: the GMM tree, at the verdict beam;
- ``median``: the median tree as a kd-tree modelled on DFKI's (:class:`MedianKDTree`:
  median-sample nodes, max-variance splits), greedy descent (about 2 log2 N evaluations);
- ``median_budget``: the same kd-tree with a beam, the smallest whose mean number of
  evaluations reaches the k-means tree's at the verdict beam (equal budget; column ``beam``);
- ``median_means``: our median-split tree (node means and the k-means tree's beam),
  a variant row;
- ``random``: the best of ``n_random`` fresh GMM samples; ``brute_force``: the exact best
  of the trees' samples.

Computation (the same selections, errors and evaluation counts as one query at a time, at
a fraction of the cost): the key-frame poses of every tree's samples and node means are
computed once (:class:`KeyFramePositionIndex`), and the queries of one constraint kind
run in lockstep (``search_many`` of the trees: one vectorised objective call per tree
level for all queries; :func:`random_search_many`). Column ``time_s`` is a method's time
for the queries of a kind divided evenly over them.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import replace
from typing import Any

import numpy as np
import pandas as pd

from ....claims import EvaluationResult, judge_claims
from ....core.joint_map import JointMap
from ...claims import CLAIMS
from ..constraints import ConstraintStack, random_constraints
from ..primitive import MotionPrimitive
from ..settings import THESIS_BUDGET, GraphSettings, SearchSettings
from ..trees import (
    KeyFramePositionIndex,
    MedianKDTree,
    SearchResult,
    SpacePartitioningTree,
    random_search_many,
    select_beam,
)
from .common import semantic_index

CONSTRAINT_KINDS = ("position", "orientation", "pose")
METHODS = ("kmeans", "gmm", "median", "median_budget", "median_means", "random", "brute_force")


COLUMNS = ["kind", "query", "method", "beam", "error", "n_evals", "time_s"]


def _build_trees(samples: np.ndarray, leaf_size: int, seed: int) -> tuple[dict, list[dict]]:
    """The k-means, GMM, median (DFKI's kd-tree) and median-means trees over ``samples``,
    and one row per tree (method, n_nodes, depth, build_s)."""
    trees, rows = {}, []
    for name in ("kmeans", "gmm", "median", "median_means"):
        t0 = time.perf_counter()
        if name == "median":
            trees[name] = MedianKDTree(samples)
        else:
            kind = "median" if name == "median_means" else name
            trees[name] = SpacePartitioningTree(samples, kind, leaf_size=leaf_size, seed=seed)
        rows.append(
            dict(method=name, n_nodes=trees[name].n_nodes, depth=trees[name].depth, build_s=time.perf_counter() - t0)
        )
    return trees, rows


def _timed_rows(
    queries: Mapping[str, list], name: str, beam: int, search_all: Callable[[str], list[SearchResult]]
) -> list[tuple]:
    """Rows (:data:`COLUMNS`) of one method: ``search_all(kind)`` answers all queries of a kind
    at once; its time is shared evenly by them."""
    out = []
    for kind, qs in queries.items():
        t0 = time.perf_counter()
        found = search_all(kind)
        dt = (time.perf_counter() - t0) / max(len(qs), 1)
        out += [(kind, q, name, beam, r.error, r.n_evals, dt) for q, r in enumerate(found)]
    return out


def _sorted_table(rows: list[tuple], beam: int, budget_beam: int, kinds: Sequence[str]) -> pd.DataFrame:
    """The per-query table: columns ``selected`` (the rows the verdicts use: every method but
    the k-means tree, which only at ``beam``) and ``budget_beam`` (the k-means rows at
    ``budget_beam``), sorted by kind, query, method, beam."""
    table = pd.DataFrame(rows, columns=COLUMNS)
    km = table["method"] == "kmeans"
    table.insert(4, "selected", ~km | (table["beam"] == beam))
    table.insert(5, "budget_beam", km & (table["beam"] == budget_beam))
    order = {m: i for i, m in enumerate(METHODS)}
    return table.sort_values(
        ["kind", "query", "method", "beam"],
        key=lambda c: (
            c.map(order)
            if c.name == "method"
            else (c.map({k: i for i, k in enumerate(kinds)}) if c.name == "kind" else c)
        ),
        kind="stable",
    ).reset_index(drop=True)


def _kd_at_budget(
    tree: MedianKDTree, run: Callable[[int], list[tuple]], target: float
) -> tuple[list[tuple], list[tuple]]:
    """The kd-tree's rows at beam 1 (greedy descent, DFKI's) and at the smallest beam whose
    mean evaluations per query reach ``target`` (``run(beam)``: rows of all queries at that
    beam; the beam grows until the mean stops growing, at most to the tree's node count)."""
    greedy = run(1)
    rows, beam, mean = greedy, 1, float(np.mean([r[5] for r in greedy]))
    while mean < target and beam < tree.n_nodes:
        beam += 1
        wider = run(beam)
        wider_mean = float(np.mean([r[5] for r in wider]))
        if wider_mean <= mean:  # every node reachable is visited already
            break
        rows, mean = wider, wider_mean
    return greedy, rows


def search_comparison(
    primitive: MotionPrimitive,
    position_joint: int,
    pose_joints: Sequence[int],
    settings: SearchSettings,
    seed: int,
    kinds: Sequence[str] = CONSTRAINT_KINDS,
) -> tuple[pd.DataFrame, pd.DataFrame]:
    """Fig. 4.12 for one primitive: random constraints of each kind at the last canonical
    frame (Eq. 4.2), met by fresh GMM samples; the best sample found by each tree (the
    k-means tree at every candidate beam), by random sampling and by brute force over the
    tree's samples. The verdicts use the k-means tree at ``settings.beam`` (the GMM and
    ``median_means`` trees run at it), never a beam chosen from the evaluation counts; the
    budget beam (:func:`~motionvar.du2022.graph.trees.select_beam` of the k-means tree's
    mean evaluations over all queries of this primitive) is marked beside it. The kd-tree
    runs greedily (``median``) and at the k-means tree's mean evaluations at the verdict
    beam (``median_budget``). Samples, constraints and trees draw from ``seed``.

    Returns (per-query table: kind, query, method, beam, selected, budget_beam, error,
    n_evals, time_s; per-tree table: method, n_nodes, depth, build_s).
    """
    st = settings
    rng = np.random.default_rng(seed)
    samples = primitive.sample(st.n_samples, rng)
    trees, tree_rows = _build_trees(samples, st.leaf_size, seed)
    last = primitive.n_frames - 1
    joints = [int(position_joint)] + [int(j) for j in pose_joints if int(j) != int(position_joint)]
    t0 = time.perf_counter()
    exact = KeyFramePositionIndex(primitive, samples, [last], joints)
    tree_rows.append(dict(method="brute_force", n_nodes=len(samples), depth=0, build_s=time.perf_counter() - t0))
    # the key-frame poses of every latent vector a search can evaluate, computed once (module docstring)
    poses = {
        name: exact if tree.points is samples else KeyFramePositionIndex(primitive, tree.points, [last], joints)
        for name, tree in trees.items()
    }
    queries = {}
    for kind in kinds:
        cons_joints = [int(position_joint)] if kind != "pose" else [int(j) for j in pose_joints]
        queries[kind] = random_constraints(primitive, kind, st.n_queries, cons_joints, last, rng)
    stacks = {kind: ConstraintStack([[c] for c in qs]) for kind, qs in queries.items()}

    def tree_run(name: str, beam: int, tree_name: str | None = None) -> list[tuple]:
        tree_name = tree_name or name
        tree, n = trees[tree_name], st.n_queries
        return _timed_rows(
            queries, name, beam, lambda k: tree.search_many(poses[tree_name].objective_many(stacks[k]), n, beam)
        )

    rows = [row for b in st.candidates for row in tree_run("kmeans", b)]
    mean_evals = pd.DataFrame(rows, columns=COLUMNS).groupby("beam")["n_evals"].mean().to_dict()
    beam, budget_beam = int(st.beam), select_beam(mean_evals, st.max_evaluations)[0]
    for name in ("gmm", "median_means"):
        rows += tree_run(name, beam)
    greedy, at_budget = _kd_at_budget(
        trees["median"], lambda b: tree_run("median_budget", b, "median"), mean_evals[beam]
    )
    rows += [(k, q, "median", *rest) for k, q, _, *rest in greedy] + at_budget
    rows += _timed_rows(
        queries, "random", 0, lambda k: random_search_many(primitive, [[c] for c in queries[k]], st.n_random, rng)
    )
    # exact: the same best sample as evaluating all of them
    rows += _timed_rows(
        queries, "brute_force", 0, lambda k: [replace(exact.search([c]), n_evals=len(samples)) for c in queries[k]]
    )
    return _sorted_table(rows, beam, budget_beam, kinds), pd.DataFrame(tree_rows)


def search_primitive(
    primitive: MotionPrimitive, joint_map: JointMap, settings: GraphSettings
) -> tuple[pd.DataFrame, pd.DataFrame]:
    """:func:`search_comparison` on one primitive with ``settings.search`` and
    ``settings.seed``, with semantic joints: the position and orientation joint is
    ``search.joints[primitive.name]`` (else ``search.default_joint``), the pose constraints
    use ``search.pose_joints``. Returns (per-query table with the primitive and the joint,
    per-tree table with the primitive); KeyError naming the config key of a joint the joint
    map lacks."""
    st, name = settings.search, primitive.name
    sem = st.joint(name)
    joint = semantic_index(joint_map, primitive.skeleton, sem, f"du2022_graph.search.joints.{name}")
    pose = [semantic_index(joint_map, primitive.skeleton, j, "du2022_graph.search.pose_joints") for j in st.pose_joints]
    table, trees = search_comparison(primitive, joint, pose, st, settings.seed)
    table.insert(0, "primitive", name)
    table.insert(2, "joint", sem)
    trees.insert(0, "primitive", name)
    return table, trees


def summarize_search(table: pd.DataFrame) -> pd.DataFrame:
    """Median, quartiles, SD of the error, mean evaluations and the share under the thesis'
    120 evaluations per (primitive, kind, method, beam), with ``selected`` (the rows the
    verdicts use), ``budget_beam`` (the k-means tree's budget beam, no verdict uses it) and
    ``median_over_random`` (the median error over random sampling's)."""
    keys = [k for k in ("primitive", "kind", "method", "beam") if k in table.columns]
    g = table.groupby(keys, sort=False)
    out = g["error"].agg(
        median="median", q25=lambda x: x.quantile(0.25), q75=lambda x: x.quantile(0.75), sd="std", mean="mean"
    )
    for flag in ("budget_beam", "selected"):
        if flag in table.columns:
            out.insert(0, flag, g[flag].all())
    out["mean_evals"] = g["n_evals"].mean()
    out["share_under_120_evals"] = g["n_evals"].apply(lambda x: float(np.mean(x < THESIS_BUDGET)))
    out["mean_time_ms"] = 1e3 * g["time_s"].mean()
    out = out.reset_index()
    case = [k for k in ("primitive", "kind") if k in out.columns]
    rand = out[out["method"] == "random"].set_index(case)["median"]
    idx = pd.MultiIndex.from_frame(out[case]) if len(case) > 1 else out[case[0]]
    out.insert(
        out.columns.get_loc("median") + 1, "median_over_random", out["median"].to_numpy() / rand.reindex(idx).to_numpy()
    )
    return out


def _selected(summary: pd.DataFrame) -> pd.DataFrame:
    return summary[summary["selected"]] if "selected" in summary.columns else summary


def _by_method(summary: pd.DataFrame, values: str) -> pd.DataFrame:
    """(primitive, kind) x method table of ``values`` (median, sd) of the rows the verdicts use."""
    return _selected(summary).pivot_table(index=["primitive", "kind"], columns="method", values=values, sort=False)


def _beam_of(rows: pd.DataFrame, flag: str) -> dict[str, int]:
    """The beam of the rows marked ``flag`` per primitive (none without the column)."""
    if flag not in rows.columns or "beam" not in rows.columns:
        return {}
    marked = rows[rows[flag]]
    return {str(p): int(b) for p, b in zip(marked["primitive"], marked["beam"])}


def _kmeans_evals(per_query: pd.DataFrame) -> tuple[dict | None, dict | None]:
    """Per primitive and beam, the k-means tree's mean evaluations and its share of queries
    under the thesis' budget (None without a ``beam`` column)."""
    km = per_query[per_query["method"] == "kmeans"]
    if "beam" not in km.columns:
        return None, None
    g = km.groupby(["primitive", "beam"])["n_evals"]
    mean, share = g.mean(), g.apply(lambda x: float(np.mean(x < THESIS_BUDGET)))

    def nested(x: pd.Series) -> dict:
        return {
            str(p): {str(b): float(v) for (pp, b), v in x.items() if pp == p}
            for p in dict.fromkeys(x.index.get_level_values(0))
        }

    return nested(mean), nested(share)


def kmeans_ratio_intervals(
    per_query: pd.DataFrame, confidence: float = 0.95, resamples: int = 2000, seed: int = 0
) -> dict[tuple[str, str], tuple[float, float]]:
    """Per (primitive, constraint kind): the percentile bootstrap interval (``scipy.stats.bootstrap``,
    paired: a resample draws whole queries) of the k-means tree's median error at the verdict
    beam over random sampling's, the ratio Fig. 4.12's halving claims compare with 0.5."""
    from scipy.stats import bootstrap

    chosen = per_query[per_query["selected"]] if "selected" in per_query.columns else per_query
    keys = [c for c in ("primitive", "kind", "joint", "query") if c in chosen.columns]
    if not {"primitive", "kind", "error"} <= set(chosen.columns):
        return {}
    errors = chosen[chosen["method"].isin(["kmeans", "random"])].pivot_table(
        index=keys, columns="method", values="error", sort=False
    )
    if not {"kmeans", "random"} <= set(errors.columns):
        return {}

    def ratio(km, rand, axis=-1):
        return np.median(km, axis=axis) / np.median(rand, axis=axis)

    out = {}
    for (p, k), case in errors.dropna().groupby(level=["primitive", "kind"], sort=False):
        if len(case) < 2:
            continue
        ci = bootstrap(
            (case["kmeans"].to_numpy(), case["random"].to_numpy()),
            ratio,
            paired=True,
            vectorized=True,
            n_resamples=resamples,
            confidence_level=confidence,
            method="percentile",
            rng=np.random.default_rng(seed),
        ).confidence_interval
        out[(str(p), str(k))] = (float(ci.low), float(ci.high))
    return out


def fig4_12_measurements(summary: pd.DataFrame, per_query: pd.DataFrame) -> dict[str, Any]:
    """What the Fig. 4.12 claims are judged on, from :func:`summarize_search` output (with a
    ``primitive`` column) and the per-query table: per (primitive, kind) case the median
    error and its SD for each method at the verdict beam, and the k-means tree's median at
    every beam (None without a ``beam`` column); per primitive the verdict beam, the budget
    beam and the kd-tree's beam at the k-means tree's budget, the mean evaluations of each
    method; the samples a tree holds (brute force's evaluations); and for the k-means tree
    at the verdict beam the number of queries, their share under the thesis' budget and
    their mean evaluations, with the mean evaluations and the share per primitive and beam; per
    case the bootstrap interval of the k-means / random ratio (:func:`kmeans_ratio_intervals`)."""
    med, sd = _by_method(summary, "median"), _by_method(summary, "sd")
    km_summary = summary[summary["method"] == "kmeans"]
    by_beam = (
        km_summary.pivot_table(index=["primitive", "kind"], columns="beam", values="median", sort=False)
        if "beam" in km_summary.columns
        else pd.DataFrame()
    )
    intervals = kmeans_ratio_intervals(per_query)
    cases = []
    for p, k in med.index:
        row = by_beam.loc[(p, k)] if not by_beam.empty and (p, k) in by_beam.index else None
        cases.append(
            {
                "primitive": str(p),
                "kind": str(k),
                "median": {str(meth): float(v) for meth, v in med.loc[(p, k)].items()},
                "sd": {str(meth): float(v) for meth, v in sd.loc[(p, k)].items()},
                "kmeans_by_beam": None if row is None else {str(b): float(v) for b, v in row.items()},
                "kmeans_over_random_interval": intervals.get((str(p), str(k))),
            }
        )
    chosen = per_query[per_query["selected"]] if "selected" in per_query.columns else per_query
    km = chosen[chosen["method"] == "kmeans"]
    evals = chosen.groupby(["primitive", "method"])["n_evals"].mean() if "primitive" in chosen.columns else None
    by_beam_evals, by_beam_share = _kmeans_evals(per_query)
    brute = per_query.loc[per_query["method"] == "brute_force", "n_evals"]
    return {
        "cases": cases,
        "beam": _beam_of(km_summary, "selected"),
        "budget_beam": _beam_of(km_summary, "budget_beam"),
        "median_budget_beam": _beam_of(summary[summary["method"] == "median_budget"], "selected"),
        "mean_evals": None
        if evals is None
        else {
            str(p): {str(m): float(evals[p][m]) for m in evals[p].index}
            for p in dict.fromkeys(evals.index.get_level_values(0))
        },
        "n_samples": int(brute.max()) if len(brute) else 0,
        "budget": THESIS_BUDGET,
        "kmeans_queries": len(km),
        "kmeans_share_under_budget": float(np.mean(km["n_evals"] < THESIS_BUDGET)),
        "kmeans_mean_evals": float(km["n_evals"].mean()),
        "kmeans_evals_by_beam": by_beam_evals,
        "kmeans_share_under_budget_by_beam": by_beam_share,
    }


def evaluate_fig4_12(queries: pd.DataFrame) -> EvaluationResult:
    """Fig. 4.12 over the per-query tables of all primitives (:func:`search_primitive`,
    concatenated): error summary per primitive, constraint kind, method and beam (timings
    left out: they are not reproducible), the claims, and the queries for the box plots."""
    if "beam" in queries.columns:
        queries = queries.astype({"beam": int})
    summary = summarize_search(queries).drop(columns="mean_time_ms")
    measurements = fig4_12_measurements(summary, queries)
    claims = judge_claims(CLAIMS, "du2022_fig4_12", measurements)
    return EvaluationResult(summary, claims, {"queries": queries}, measurements)
