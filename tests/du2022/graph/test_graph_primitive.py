"""Du 2022 ch. 4 motion primitives (Sec. 4.3): chain forward kinematics, the fitted primitive (SFPCA, GMM by BIC), sampling, log-probability and model files."""

from __future__ import annotations

import json

import numpy as np
import pytest
from graph_toy import OPT

from motionvar.du2022.graph import MotionPrimitive, PrimitiveOptions, select_gmm
from motionvar.du2022.graph.kinematics import ancestors, chain_fk


def test_chain_fk_matches_full_fk(clips):
    m = clips[0]
    pos = m.positions()
    p, _ = chain_fk(m.rotations, m.root_pos, m.skeleton.offsets, m.skeleton.parents, [27, 4])
    assert np.allclose(p, pos[:, [27, 4]])
    assert list(ancestors(m.skeleton.parents, [4])) == [0, 1, 2, 3, 4]


def test_primitive_fit_reconstructs_and_unwarps(prim, clips):
    assert prim.n_latent == 5 and prim.n_frames in [c.n_frames for c in clips]
    # the chosen GMM has the lowest BIC of the searched range (Eq. 4.1)
    assert prim.gmm_.n_components == min(prim.gmm_scores_, key=prim.gmm_scores_.get)
    # back-projected training scores put the hands where the (warped) clips end
    last = prim.n_frames - 1
    pos, _ = prim.key_frame_pose(prim.training_latent_, [last], [27])
    true = np.stack([c.positions()[-1, 27] for c in clips])
    assert np.median(np.linalg.norm(pos[:, 0, 0] - true, axis=-1)) < 2.0
    # the time function restores each clip's own length (within a few frames)
    lengths = [m.n_frames for m in prim.to_motions(prim.training_latent_)]
    assert np.max(np.abs(np.array(lengths) - [c.n_frames for c in clips])) <= 3
    assert all(m.n_frames == prim.n_frames for m in prim.to_motions(prim.training_latent_[:2], warp_time=False))


def test_primitive_sample_and_log_prob(prim):
    S = prim.sample(500, 0)
    assert S.shape == (500, prim.n_latent)
    assert np.allclose(prim.log_prob(S), prim.gmm_.score_samples(S))
    assert np.array_equal(S, prim.sample(500, 0))
    with pytest.raises(ValueError, match="latent vectors must be"):
        prim.log_prob(np.zeros((2, prim.n_latent + 1)))


def test_primitive_save_load_roundtrip(prim, tmp_path):
    files = prim.save(tmp_path / "walk")
    assert sorted(f.suffix for f in files) == [".json", ".npz"]
    with np.load(files[0], allow_pickle=False) as z:  # no pickles inside
        assert "components" in z.files
    meta = json.loads(files[1].read_text())
    assert meta["name"] == "walk_leftStance" and meta["options"]["gmm_criterion"] == "bic"
    back = MotionPrimitive.load(tmp_path / "walk.npz")
    S = prim.sample(20, 1)
    assert np.allclose(back.log_prob(S), prim.log_prob(S))
    assert np.allclose(back.coefs(S), prim.coefs(S))
    assert np.array_equal(back.sample(20, 1), prim.sample(20, 1))


def test_primitive_bad_input(clips, tmp_path):
    with pytest.raises(ValueError, match="at least 3 clips"):
        MotionPrimitive("x", OPT).fit(clips[:2])
    with pytest.raises(ValueError, match="gmm_components"):
        MotionPrimitive("x", PrimitiveOptions(gmm_components=(3, 1))).fit(clips)
    with pytest.raises(ValueError, match="not a readable motion primitive"):
        MotionPrimitive.load(tmp_path / "missing")


def test_select_gmm_bic_finds_clusters():
    rng = np.random.default_rng(0)
    X = np.concatenate([rng.normal(c, 0.3, size=(80, 2)) for c in ((0, 0), (5, 0), (0, 5))])
    gmm, scores = select_gmm(X, (1, 6))
    assert gmm.n_components == 3 and set(scores) == set(range(1, 7))
