"""Egges 2004 small variations (Sec. 6), synthesis and integration (Sec. 5.4, 7), and the evaluation measures, baselines and figures."""

import numpy as np
import pytest

from motionvar.core import Motion, cmu_joint_map
from motionvar.core.quaternions import qangle
from motionvar.egges2004 import (
    PosturePCA,
    add_variations,
    analyse_recording,
    blend_motions,
    extrema_pairs,
    find_extrema,
    fit_variation_model,
    generate_idle,
    idle_between,
    joint_mask,
    posture_distance,
    synthesize_balance,
)


def test_find_extrema_alternate_and_respect_epsilon():
    t = np.linspace(0, 4 * np.pi, 400)
    x = np.sin(t) + 0.01 * np.random.default_rng(0).normal(size=t.size)
    idx, is_max = find_extrema(x, eps=0.5)
    assert len(idx) == 4 and np.all(is_max[::2] != is_max[1::2])
    assert np.allclose(np.abs(x[idx]), 1, atol=0.05)
    pairs = extrema_pairs(x, fps=100.0, eps=0.5)
    assert pairs.shape == (3, 2) and np.allclose(pairs[:, 0], 1000 * np.pi / (t[1] - t[0]) / 100, rtol=0.1)
    with pytest.raises(ValueError, match="eps"):
        find_extrema(x, 0.0)


def test_variation_model_generates_curves_like_the_data():
    t = np.arange(600) / 30.0
    segs = [np.stack([np.sin(2 * np.pi * 0.3 * t + ph), 0.1 * np.sin(2 * np.pi * 0.7 * t)], 1) for ph in (0, 1, 2)]
    model = fit_variation_model(segs, [0, 1], fps=30.0, eps_sd=0.5, n_clusters=3, seed=0)
    a = model.generate(900, 30.0, np.random.default_rng(5))
    b = model.generate(900, 30.0, np.random.default_rng(5))
    assert a.shape == (900, 2) and np.array_equal(a, b) and np.allclose(a[0], 0)
    assert np.abs(a[:, 0]).max() <= 1.05 and np.abs(a[:, 1]).max() <= 0.106
    assert a[:, 0].std() > 0.3
    with pytest.raises(ValueError, match="n_clusters"):
        fit_variation_model(segs, [0], 30.0, 0.5, 0, 0)


def test_balance_synthesis_is_continuous_and_seeded(toy):
    recs, pca, analysed, db = toy
    a, events = synthesize_balance(db, 1200, np.random.default_rng(3))
    b, _ = synthesize_balance(db, 1200, np.random.default_rng(3))
    assert a.shape == (1200, pca.n_dims) and np.array_equal(a, b)
    kinds = [e.kind for e in events]
    assert kinds[0] == "rest" and all(k1 != k2 for k1, k2 in zip(kinds, kinds[1:]))
    step = np.sqrt(posture_distance(a[1:], a[:-1], db.weights))
    data_step = np.sqrt(posture_distance(analysed[0].pcs[1:], analysed[0].pcs[:-1], db.weights))
    assert step.max() <= 2 * data_step.max()


def test_idle_between_starts_at_p0_and_ends_at_p1(toy):
    _, _, analysed, db = toy
    p0, p1 = analysed[0].pcs[20], analysed[1].pcs[300]  # left -> right
    for n in (900, 40):  # plenty of time, and too little (time-scaled shifts)
        out, events = idle_between(db, p0, p1, n, np.random.default_rng(1))
        assert out.shape == (n, p0.size)
        assert np.allclose(out[0], p0) and np.allclose(out[-1], p1, atol=1e-12)
        assert events[-1].stop == n - 1
    out, events = idle_between(db, p0, p0, 300, np.random.default_rng(2), close_distance=np.inf)
    assert np.allclose(out[-1], p0)


def test_generated_idle_is_a_motion_with_the_subjects_postures(toy):
    recs, pca, _, db = toy
    m = generate_idle(db, pca, recs[0][0].skeleton, 20.0, np.random.default_rng(0))
    assert m.n_frames == 601 and m.fps == 30.0
    from motionvar.egges2004 import support_ratio

    lam = support_ratio(m, cmu_joint_map())
    assert lam.min() < 0.42 and lam.max() > 0.58
    with pytest.raises(ValueError, match="duration"):
        generate_idle(db, pca, recs[0][0].skeleton, 0.0, np.random.default_rng(0))


def test_blend_with_masks_and_add_variations(toy):
    recs, pca, _, _ = toy
    idle, other = recs[0][0].slice(0, 50), recs[1][0].slice(0, 50)
    other = Motion(other.skeleton, other.root_pos + 10, other.rotations, other.fps)
    sk, jm = idle.skeleton, cmu_joint_map()
    mask = joint_mask(sk, jm, ["legs", "upper_body"])
    arms = np.flatnonzero(mask == 0)
    assert arms.size > 0
    full = blend_motions(idle, other, 1.0, mask)
    assert np.max(qangle(full.rotations[:, arms], other.rotations[:, arms])) < 1e-9
    legs = jm.group_indices(sk)["legs"]
    assert np.max(qangle(full.rotations[:, legs], idle.rotations[:, legs])) < 1e-9
    none = blend_motions(idle, other, 0.0, mask)
    assert np.max(qangle(none.rotations, other.rotations)) < 1e-9 and np.allclose(none.root_pos, other.root_pos)
    same = add_variations(idle, np.zeros((50, 3)), np.arange(3), pca)
    assert np.max(qangle(same.rotations, idle.rotations)) < 1e-9
    with pytest.raises(ValueError, match="joint groups"):
        joint_mask(sk, jm, ["tail"])
    with pytest.raises(ValueError, match="same skeleton and length"):
        blend_motions(idle, other.slice(0, 10), 1.0, mask)


def test_window_features_sets():
    from motionvar.egges2004.evaluations.identification import feature_subset, window_features

    rng = np.random.default_rng(0)
    pcs, lam = rng.normal(size=(1200, 12)), rng.uniform(0.3, 0.7, 1200)
    full = window_features(pcs, lam, 30.0, 10.0, n_pcs=5, margin=0.1)
    dyn = window_features(pcs, lam, 30.0, 10.0, n_pcs=5, margin=0.1, feature_set="dynamics")
    posture = window_features(pcs, lam, 30.0, 10.0, n_pcs=5, margin=0.1, feature_set="posture")
    assert full.shape == (4, 5 + 5 + 1 + 3 + 1 + 9) and dyn.shape == (4, 5 + 1 + 9) and posture.shape == (4, 5 + 4)
    assert np.all(np.isfinite(full))
    assert np.array_equal(feature_subset(full, "dynamics", 5), dyn)
    assert np.array_equal(feature_subset(full, "posture", 5), posture)
    # movement-only features do not see the posture held: shifting every PC changes none of them
    assert np.allclose(window_features(pcs + 3.0, lam, 30.0, 10.0, 5, 0.1, feature_set="dynamics"), dyn)
    with pytest.raises(ValueError, match="feature_set"):
        window_features(pcs, lam, 30.0, 10.0, 5, 0.1, feature_set="mean")
    with pytest.raises(ValueError, match="feature_set"):
        feature_subset(full, "mean", 5)
    with pytest.raises(ValueError, match="window"):
        window_features(pcs[:100], lam[:100], 30.0, 10.0, 5, 0.1)


def test_mcnemar_greater_counts_discordant_pairs():
    from scipy.stats import binomtest

    from motionvar.egges2004.evaluations.identification import mcnemar_greater

    a = np.array([1, 1, 1, 1, 1, 1, 1, 0, 0, 1], dtype=bool)
    b = np.array([0, 0, 0, 0, 0, 0, 1, 1, 0, 1], dtype=bool)
    better, worse, p = mcnemar_greater(a, b)
    assert (better, worse) == (6, 1) and p == pytest.approx(binomtest(6, 7, 0.5, alternative="greater").pvalue)
    assert mcnemar_greater(b, a)[2] > 0.9  # one-sided: B is not better than A
    assert mcnemar_greater(a, a) == (0, 0, 1.0)  # no discordant pair: no evidence
    with pytest.raises(ValueError, match="paired"):
        mcnemar_greater(a, b[:5])


def test_movement_only_features_identify_people_who_differ_only_in_movement():
    """Ground truth of the movement-only features (Sec. 5.6: "the way a person changes posture"):
    four synthetic people with one body, stance and set of resting postures who differ only in
    how they move (sway, breathing rate, how often and how fast they shift, head and arm
    movements; motionvar.synth.idle.movement_twin) are named from movement-only features and not
    from posture-only ones, through the posture PCA and the classifier of the evaluation."""
    from motionvar.egges2004.evaluations.identification import REC, identification_table
    from motionvar.egges2004.settings import Egges2004Settings
    from motionvar.synth import idle as synth_idle
    from motionvar.synth.subjects import make_subjects

    twins = [synth_idle.movement_twin(make_subjects(1, seed=0)[0], k) for k in range(4)]
    params = synth_idle.IdleParams(duration_s=60.0, fps=15.0, start_xz=(0.0, 0.0), heading_deg=0.0)
    clips = {
        f"{k + 1:02d}": [
            synth_idle.generate_idle(t, params, np.random.default_rng(100 * k + c), st)[0] for c in range(5)
        ]
        for k, (t, st) in enumerate(twins)
    }
    pca = PosturePCA(0.01).fit([ms[0] for ms in clips.values()])  # one training clip each spans the postures
    jm = cmu_joint_map()
    analysed = {s: [analyse_recording(m, pca, jm, f"{s}_{c}") for c, m in enumerate(ms)] for s, ms in clips.items()}
    train = [(s, r.pcs, r.support) for s, rs in analysed.items() for r in rs[:3]]
    held = {REC: [(s, r.pcs, r.support) for s, rs in analysed.items() for r in rs[3:]]}
    settings = Egges2004Settings.from_dict({"identification": {"window_s": 10.0}})
    table, _ = identification_table(train, held, list(clips), params.fps, settings)
    p = table.set_index("features")["p_value"]
    assert p["dynamics"] < settings.identification.alpha, table
    assert p["posture"] >= settings.identification.alpha, table


def test_spectral_distance_is_zero_for_equal_spectra_and_3_db_for_half_the_power():
    from motionvar.egges2004.evaluations.repetition import power_spectra, spectral_distance_db

    rng = np.random.default_rng(0)
    f, psd = power_spectra(rng.normal(size=(400, 2)), 20.0, 40)
    assert f[0] > 0 and psd.shape == (len(f), 2)  # the zero frequency is dropped
    assert np.allclose(spectral_distance_db(psd, psd), 0.0)
    assert np.allclose(spectral_distance_db(psd, 2 * psd), 10 * np.log10(2))  # about 3 dB
    assert spectral_distance_db(np.zeros_like(psd), np.zeros_like(psd)).tolist() == [0.0, 0.0]
    assert np.all(spectral_distance_db(np.zeros_like(psd), psd) > 50)  # no movement where there is some
    with pytest.raises(ValueError, match="same shape"):
        spectral_distance_db(psd, psd[:, :1])
    with pytest.raises(ValueError, match="two frames"):
        power_spectra(np.zeros((1, 2)), 20.0, 40)


def test_structure_distances_tell_white_noise_from_sway():
    from motionvar.egges2004.evaluations.repetition import GEN_VAR, REC_VAR, WHITE_VAR, structure_distances

    rng = np.random.default_rng(0)
    kernel = np.hanning(25) / np.hanning(25).sum()

    def sway(n):
        return np.stack([np.convolve(c, kernel, "same") for c in rng.normal(size=(2, n))], axis=1)

    rec = sway(1500)
    seqs = {REC_VAR: rec, GEN_VAR: sway(3000) + 5.0, WHITE_VAR: rng.normal(size=(3000, 2)) * rec.std(axis=0)}
    d = structure_distances(seqs, 25.0, 50)
    assert set(d) == set(seqs) and np.all(d[GEN_VAR] < 3.0) and np.all(d[WHITE_VAR] > 10.0)  # offset removed
    assert np.all(d[REC_VAR] < 3.0)  # the recordings' halves
    short = structure_distances({REC_VAR: rec[:99], GEN_VAR: rec}, 25.0, 50)
    assert all(len(v) == 0 for v in short.values())


def test_window_best_match_sees_a_loop():
    from motionvar.egges2004.baselines import loop_frames
    from motionvar.egges2004.evaluations.repetition import window_best_match

    rng = np.random.default_rng(0)
    clip = np.cumsum(rng.normal(size=(130, 3)), axis=0)
    looped = window_best_match(loop_frames(clip, 1000), window=50, stride=1)
    fresh = window_best_match(np.cumsum(rng.normal(size=(1000, 3)), axis=0), window=50, stride=1)
    assert np.all(looped > 0.999) and np.median(fresh) < 0.9
    with pytest.raises(ValueError, match="two windows"):
        window_best_match(clip[:60], 50, 1)


def test_speed_is_the_mean_of_the_runs_on_named_hardware(toy):
    from motionvar.egges2004.evaluations.speed import generation_seconds, machine

    _, pca, _, db = toy
    t = generation_seconds(db, pca, 300, seed=0, repeats=2)
    assert set(t) == {"balance", "variations", "reconstruct", "total"} and t["total"] > 0
    assert t["total"] == pytest.approx(t["balance"] + t["variations"] + t["reconstruct"])
    hw = machine()
    assert hw["cpu"] and hw["cores"] >= 1 and 1 <= hw["usable_cores"] <= hw["cores"]
    with pytest.raises(ValueError, match="egges2004.speed.repeats"):
        generation_seconds(db, pca, 300, seed=0, repeats=0)


def test_junction_steps():
    from motionvar.egges2004.evaluations.fitting import all_steps, junction_steps

    x = np.concatenate([np.zeros(5), np.arange(1, 6) * 2.0])[:, None]
    step, accel = junction_steps(x, np.array([4, 0, 9]), np.ones(1))
    assert step.tolist() == [2.0] and accel.tolist() == [2.0]
    assert all_steps(x, np.ones(1))[0].shape == (8,)


def test_idle_baselines():
    from motionvar.egges2004.baselines import loop_frames, perlin_pcs

    assert loop_frames(np.arange(3), 7).tolist() == [0, 1, 2, 0, 1, 2, 0]
    base, sds = np.arange(6.0), np.array([0.5, 0.1])
    a = perlin_pcs(base, sds, 0.5, 3000, 30.0, seed=1)
    assert np.allclose(a.std(axis=0)[:2], sds) and np.allclose(a[:, 2:], base[2:])
    assert np.allclose(a.mean(axis=0), base)
    assert np.array_equal(a, perlin_pcs(base, sds, 0.5, 3000, 30.0, seed=1))
    with pytest.raises(ValueError, match="loop_frames"):
        loop_frames(np.zeros(0), 3)
    with pytest.raises(ValueError, match="SDs"):
        perlin_pcs(base, np.ones(7), 0.5, 10, 30.0, 0)


def test_figures_draw(toy):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from motionvar.egges2004.figures import plot_category_graph, plot_fitted_animation, plot_pc_extrema

    _, _, _, db = toy
    fig, axes = plt.subplots(1, 3)
    plot_category_graph(axes[0], db.graph, "toy")
    x = np.sin(np.linspace(0, 12, 300))
    idx, is_max = find_extrema(x, 0.5)
    plot_pc_extrema(axes[1], x, 30.0, idx, is_max, 0)
    a = db.animations[0]
    plot_fitted_animation(axes[2], a[:, 0], {"linear": a[:, 0] + 1}, a[0, 0] + 1, a[-1, 0] + 1, 30.0)
    assert len(axes[0].patches) >= 3 + 6
    plt.close(fig)
