"""Du 2022 ch. 4 the Morphable Graph (Sec. 4.5): the graph from metadata, placing motion, following a path, greedy and joint optimisation, coverage."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from motionvar.core import cmu_joint_map
from motionvar.du2022.graph import (
    MorphableGraph,
    Objective,
    Path2D,
    SpacePartitioningTree,
    StepChain,
    StepGoal,
    SynthesisSettings,
    concatenate_steps,
    follow_path,
    optimize_chain,
    place_motion,
)
from motionvar.du2022.graph.evaluations import coverage
from motionvar.du2022.graph.morphable_graph import _to_local

GREEDY = SynthesisSettings(max_steps=6, max_nfev=30, look_ahead=1, joint_steps=0)  # T = 1, no line 9


def test_graph_from_metadata():
    meta = pd.DataFrame(
        dict(
            source_clip=["a", "a", "a", "b", "b"],
            start_frame=[0, 30, 60, 0, 20],
            primitive=["walk_start", "walk_leftStance", "walk_end", "pick_reach", "pick_retrieve"],
        )
    )
    g = MorphableGraph.from_metadata(meta.iloc[::-1])  # order of rows does not matter
    assert g.successors("walk_start") == ["walk_leftStance"]
    assert g.successors("walk_leftStance") == ["walk_end"]
    assert g.start_nodes == {"walk_start": 1, "pick_reach": 1} and g.end_nodes == {"walk_end": 1, "pick_retrieve": 1}
    assert len(g.edge_table()) == 3
    with pytest.raises(ValueError, match="lacks columns"):
        MorphableGraph.from_metadata(meta.drop(columns="start_frame"))
    with pytest.raises(KeyError, match="no node"):
        g.successors("run")


def test_place_motion_and_local_frame(clips):
    m = clips[0]
    heading = np.array([0.0, 0.0, 1.0])  # +z
    placed = place_motion(m, np.array([10.0, 20.0]), heading)
    # the aligned clip moves along +x; placed, it moves along +z from (10, 20)
    d = placed.root_pos[-1] - placed.root_pos[0]
    assert abs(d[0]) < 1e-6 and d[2] > 0 and np.allclose(placed.root_pos[0, [0, 2]], [10, 20])
    world_end = placed.root_pos[-1, [0, 2]]
    assert np.allclose(_to_local(world_end, np.array([10.0, 20.0]), heading), m.root_pos[-1, [0, 2]])


def test_follow_straight_path(prim, right):
    prims = {"walk_leftStance": prim, "walk_rightStance": right}
    meta = pd.DataFrame(
        dict(source_clip=["a"] * 4, start_frame=[0, 1, 2, 3], primitive=["walk_leftStance", "walk_rightStance"] * 2)
    )
    g = MorphableGraph.from_metadata(meta, prims)
    trees = {k: SpacePartitioningTree(p.sample(300, 0), "kmeans", leaf_size=8) for k, p in prims.items()}
    path = Path2D(np.array([[0.0, 0.0], [200.0, 0.0]]))
    steps = follow_path(g, trees, path, cmu_joint_map(), GREEDY)
    names = [s.primitive for s in steps]
    assert len(names) >= 2 and all(a != b for a, b in zip(names[:-1], names[1:]))  # the graph alternates stances
    walk = concatenate_steps(steps)
    assert walk.n_frames == sum(s.motion.n_frames for s in steps) - (len(steps) - 1)
    assert walk.root_pos[-1, 0] > 100.0 and abs(walk.root_pos[-1, 2]) < 20.0
    with pytest.raises(ValueError, match="path"):
        Path2D(np.zeros((1, 2)))


def test_step_chain_errors_match_the_step_constraints(prim, right, joints):
    """The chained world errors of StepChain are the errors of each step's own position and
    heading constraints in its aligned frame, with each step placed where the one before ends."""
    from motionvar.du2022.graph.morphable_graph import _goal_constraints, _step_end

    js = (joints["hips"], joints["left_hip"], joints["right_hip"])
    prims = [prim, right, prim]
    S = [p.sample(1, k)[0] for k, p in enumerate(prims)]
    goals = [StepGoal([40.0 * (k + 1), 5.0 * k], [1.0, 0.0, 0.2 * k]) for k in range(3)]
    start, heading = np.array([3.0, -2.0]), np.array([0.9, 0.0, 0.3])
    chain = StepChain(prims, goals, start, heading, *js)
    err = chain.errors(np.concatenate(S)[None])[0]
    pos, h = start, heading
    for k, p in enumerate(prims):
        cons = _goal_constraints(p, goals[k], pos, h, *js)
        assert np.allclose(err[k], Objective(p, cons).errors(S[k][None])[0], atol=1e-6)
        pos, h = _step_end(p, S[k], pos, h, js)
    with pytest.raises(ValueError, match="one goal per step"):
        StepChain(prims, goals[:2], start, heading, *js)


@pytest.mark.parametrize("corner", [False, True])
def test_joint_optimisation_never_worse_than_greedy(prim, right, corner):
    """Algorithm 1 line 9 starts from the greedy walk and least squares only accepts steps
    that lower the stacked residuals, so the walk's residual cost (constraint errors plus
    the likelihood term) never grows. The path error alone falls on a path the toy steps
    can follow (a straight line at an angle); at a corner the toy primitives cannot turn at
    all (every clip walks straight, the heading error stays 30 degrees), so line 9 can only
    trade position against likelihood there: mean step error 37.9 cm against 37.85 cm
    greedy, not checked."""
    prims = {"walk_leftStance": prim, "walk_rightStance": right}
    meta = pd.DataFrame(
        dict(source_clip=["a"] * 4, start_frame=[0, 1, 2, 3], primitive=["walk_leftStance", "walk_rightStance"] * 2)
    )
    g = MorphableGraph.from_metadata(meta, prims)
    trees = {k: SpacePartitioningTree(p.sample(300, 0), "kmeans", leaf_size=8) for k, p in prims.items()}
    path = Path2D(np.array([[0.0, 0.0], [120.0, 0.0], [200.0, 80.0]] if corner else [[0.0, 0.0], [200.0, 20.0]]))
    jm = cmu_joint_map()
    runs = {}
    for label, kw in (
        ("greedy", {}),
        ("line9", dict(joint_steps="all")),
        ("last2", dict(joint_steps=2)),
        ("ahead", dict(look_ahead=2)),
        ("receding", dict(look_ahead=2, receding_horizon=True)),
    ):
        runs[label] = follow_path(g, trees, path, jm, GREEDY.replace(**kw))
    greedy, line9 = runs["greedy"], runs["line9"]
    assert [s.primitive for s in line9] == [s.primitive for s in greedy]  # line 9 keeps the graph walk
    js = tuple(jm.index(prim.skeleton, k) for k in ("hips", "left_hip", "right_hip"))
    chain = StepChain(
        [prims[s.primitive] for s in greedy], [s.goal for s in greedy], path.points[0], path.tangent(0.0), *js
    )
    cost = {
        k: float(np.sum(chain.residuals(np.concatenate([s.fit.latent for s in v])[None], 1.0) ** 2))
        for k, v in (("greedy", greedy), ("line9", line9))
    }
    assert cost["line9"] <= cost["greedy"] + 1e-9
    mean_pos = {k: np.mean([s.fit.errors_after[0] for s in v]) for k, v in runs.items()}
    if not corner:
        assert mean_pos["line9"] <= mean_pos["greedy"] + 1e-9
    assert all(np.allclose(a.fit.latent, b.fit.latent) for a, b in zip(greedy[:-2], runs["last2"][:-2]))
    for v in runs.values():  # steps still start where the one before ends
        for a, b in zip(v[:-1], v[1:]):
            assert np.linalg.norm(b.motion.root_pos[0, [0, 2]] - a.motion.root_pos[-1, [0, 2]]) < 5.0
    ahead = runs["ahead"]  # T = 2 by the mean motions: each step optimised on its own (no receding horizon)
    assert all(np.array_equal(s.fit.errors_after, s.step_errors) for s in ahead)
    assert any(not np.array_equal(s.fit.errors_after, s.step_errors) for s in runs["receding"][:-1])
    again = follow_path(g, trees, path, jm, GREEDY.replace(look_ahead=2, receding_horizon=True, joint_steps="all"))
    twice = follow_path(g, trees, path, jm, GREEDY.replace(look_ahead=2, receding_horizon=True, joint_steps="all"))
    assert all(np.array_equal(a.fit.latent, b.fit.latent) for a, b in zip(again, twice))  # the same walk every run
    res = optimize_chain(chain, [s.fit.latent for s in greedy], 1.0, "lm", max_nfev=5)
    assert res.errors_after.shape == (len(greedy), 2) and len(res.latents) == len(greedy)
    with pytest.raises(ValueError, match="start vectors"):
        optimize_chain(chain, [greedy[0].fit.latent], 1.0, "lm", 100)
    with pytest.raises(ValueError, match="joint_steps"):
        SynthesisSettings(joint_steps="some")


def test_coverage_measures_overlap():
    from motionvar.du2022.graph.evaluations.fig4_9 import coverage_both_ways, hdr_threshold

    rng = np.random.default_rng(0)
    samples = rng.normal(size=(20000, 2))
    cov_same, _, data = coverage(samples, rng.normal(size=(400, 2)), 0.95, 128)
    cov_far, _, _ = coverage(samples, rng.normal(4.0, 1.0, size=(400, 2)), 0.95, 128)
    assert 0.88 <= cov_same <= 1.0 and cov_far < 0.3
    assert data["density"].shape == (128, 128)
    # both ways: over-spread samples cover the training points but mostly lie outside their region
    training = rng.normal(size=(60, 2))
    same = coverage_both_ways(samples, training, 0.95, 64)
    wide = coverage_both_ways(3.0 * samples, training, 0.95, 64)
    assert min(same[:2]) >= 0.88 and wide[0] == 1.0 and wide[1] < 0.5
    assert wide[2]["training_density"].shape == (64, 64) and wide[2]["training_threshold"] > 0
    # the threshold of a gridded density: its superlevel set holds the level's mass
    dens, x, y = data["density"], data["x"], data["y"]
    inside = dens[dens >= hdr_threshold(dens, x, y, 0.95)].sum() * (x[1] - x[0]) * (y[1] - y[0])
    assert 0.95 <= inside <= 0.96
