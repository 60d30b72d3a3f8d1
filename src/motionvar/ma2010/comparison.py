"""Long sequences from every method of Ma et al. 2010, Sec. 7.4 (ours, Perlin noise, a
GPLVM along a helix, RBF, style-only Kriging, a DBN: :func:`method_sequences`; Perlin noise
and the DBN at each setting of a sweep: :func:`method_variants`), and the measures that
compare them (naturalness, and variation between sequences of one method).

Every method outputs local rotations; the root of every sequence is then recovered by the
same footskate cleanup (Sec. 6.3), so that the methods differ only in their poses.

The naturalness measures are checked on the generator's ground truth first
(tests/metrics/test_metrics_motion.py): foot skating is the speed of a foot's contact point over
the frames it is in contact (0 on the generator's walks; the earlier height-threshold
measure, which scored them 13-47 cm/s, is reported beside it as ``low_joint_speed_cm_s``),
and jerk is reported for the whole body and without the root's path (root-free).
"""

from __future__ import annotations

import copy
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from ..core.motion import Motion
from ..metrics.discontinuities import count_discontinuities, peak_acceleration
from ..metrics.foot_skating import foot_skating, low_joint_speed
from ..metrics.jerk import mean_jerk, root_free_jerk
from ..metrics.pose_distance import nearest_pose_distance, pose_features, pose_set_distance
from ..models.bayesian_gplvm import BayesianGPLVM
from .baselines.dbn import LauDBN
from .baselines.gplvm import helix_trajectory
from .baselines.mukai_kuriyama import StyleClipInterpolation, mk05_kriging, rose98_rbf
from .baselines.perlin import add_rotation_noise
from .contacts import foot_contacts
from .correspondence import key_times_increase
from .representation import ClipSet, PoseCodec
from .settings import XI_DRAWS, Ma2010Settings
from .svi import ClipPrediction, StyleVariationModel, style_variation_model
from .synthesis import RootSolver, realtime_clips, sequence_motion, stitch

#: the method families of Sec. 7.4 (Perlin noise and the DBN come at each setting of their sweep)
METHODS = ("ours", "perlin", "gplvm", "rbf", "kriging", "dbn")
LABELS = {
    "ours": "ours (Ma 2010)",
    "perlin": "Perlin noise",
    "gplvm": "Bayesian GPLVM helix",
    "rbf": "RBF",
    "kriging": "Kriging (MK05)",
    "dbn": "DBN (Lau 2009)",
}


def method_variants(settings: Ma2010Settings) -> dict[str, str]:
    """The methods of Sec. 7.4 at every setting compared (key -> label), in :data:`METHODS`
    order: Perlin noise at each of ``perlin_amplitude_sweep_rad`` (key ``perlin_<rad>``), the
    DBN at each of ``dbn_max_parents_sweep`` (key ``dbn_<parents>``), the others once."""
    out: dict[str, str] = {}
    for m in METHODS:
        if m == "perlin":
            out |= {f"perlin_{a:g}": f"{LABELS[m]} {a:g} rad" for a in settings.sec7_4.perlin_amplitude_sweep_rad}
        elif m == "dbn":
            out |= {f"dbn_{p}": f"{LABELS[m]} {p} parents" for p in settings.sec7_4.dbn_max_parents_sweep}
        else:
            out[m] = LABELS[m]
    return out


def family(variant: str) -> str:
    """The method (a key of :data:`METHODS`) of a key of :func:`method_variants`."""
    return variant.split("_", 1)[0]


def clips_for_duration(clips: ClipSet, seconds: float) -> int:
    """Number of cycles whose mean duration covers ``seconds`` (one extra for trimming)."""
    mean_cycle = float(np.mean(clips.key_times[:, -1] - clips.key_times[:, 0]))
    return int(np.ceil(seconds / mean_cycle)) + 1


def trim(motion: Motion, seconds: float) -> Motion:
    """The first ``seconds`` of a motion."""
    return motion.slice(0, min(motion.n_frames, int(round(seconds * motion.fps)) + 1))


def covering(
    make: Callable[[int, np.random.Generator], Motion],
    n_clips: int,
    seconds: float,
    rng: np.random.Generator,
    max_doublings: int = 6,
) -> Motion:
    """The first ``seconds`` of ``make(n_clips, rng)``; when that motion ends earlier (its cycles
    shorter than the examples' mean, e.g. a sampled walker who steps faster), made again from
    the generator's same state with twice the cycles until it lasts (at most ``max_doublings``
    times), never from fresh draws, which would favour slow walkers: with xi drawn once per
    sequence (ours' default) the same sequence, longer; per cycle, the same cycle lengths.
    ``rng`` ends as the last ``make`` left it. A motion still short after that is returned as it
    is (a sequence that broke down)."""
    start = copy.deepcopy(rng)
    motion = make(n_clips, rng)
    for _ in range(max_doublings):
        if motion.duration >= seconds - 1.0 / motion.fps:
            break
        n_clips *= 2
        trial = copy.deepcopy(start)
        motion = make(n_clips, trial)
        rng.bit_generator.state = trial.bit_generator.state
    return trim(motion, seconds)


def ours_clips(
    model: StyleVariationModel, style: np.ndarray, n_clips: int, rng: np.random.Generator, xi_per: str
) -> ClipPrediction:
    """n_clips predicted cycles at one style, xi sampled from the network (Eq. 10) once for
    all of them (``xi_per`` "sequence": one person walks the whole sequence, the cycles are
    the same) or anew for every cycle ("clip"); config ma2010.sec7_4.xi (Sec. 7.4 does
    not say)."""
    if xi_per not in XI_DRAWS:
        raise ValueError(f"ours_clips: xi_per must be one of {list(XI_DRAWS)}; got {xi_per!r}")
    c = np.tile(np.atleast_2d(style), (n_clips, 1))
    if xi_per == "clip":
        return model.synthesize_clips(c, rng=rng)[0]
    xi = model.sample_variation(c[:1], rng=rng)
    return model.predict(c, {g: np.repeat(v, n_clips) for g, v in xi.items()})


def until_failed(pred: ClipPrediction) -> ClipPrediction:
    """The clips of ``pred`` before its first failed synthesis (key times that do not increase,
    possible under ``ma2010.model.key_timing: absolute``; at least the first clip's first frame): a
    sequence breaks down there instead of having the clip clamped into a zero-length segment."""
    ok = key_times_increase(pred.key_times)
    if ok.all():
        return pred
    n = int(np.argmin(ok))
    if n == 0:
        one = pred.key_times[:1].copy()
        one[0] = one[0, 0] + np.arange(one.shape[1]) * 1e-9  # the first frame only
        return ClipPrediction(pred.rotations[:1], one, None if pred.root_height is None else pred.root_height[:1])
    return ClipPrediction(
        pred.rotations[:n], pred.key_times[:n], None if pred.root_height is None else pred.root_height[:n]
    )


def ours_sequence(
    model: StyleVariationModel,
    style: np.ndarray,
    n_clips: int,
    solver: RootSolver,
    rng: np.random.Generator,
    xi_per: str,
    landing_rule: str,
) -> Motion:
    """Ours: n_clips cycles at one style (:func:`ours_clips`), retimed, stitched and
    root-solved."""
    pred = until_failed(ours_clips(model, style, n_clips, rng, xi_per))
    return sequence_motion(
        pred.rotations, pred.key_times, model.reference_keys_, solver, model.fps_, pred.root_height, landing_rule
    )


def interpolation_sequence(
    interp: StyleClipInterpolation,
    style: np.ndarray,
    n_clips: int,
    solver: RootSolver,
    fps: float,
    landing_rule: str,
) -> Motion:
    """RBF or plain Kriging: the same clip (one style) repeated n_clips times."""
    pred = until_failed(interp.predict(np.tile(np.atleast_2d(style), (n_clips, 1))))
    return sequence_motion(
        pred.rotations, pred.key_times, interp.reference_keys_, solver, fps, pred.root_height, landing_rule
    )


def perlin_sequences(
    clips: ClipSet,
    n_clips: int,
    solver: RootSolver,
    rng: np.random.Generator,
    amplitudes: Sequence[float],
    frequency_hz: float,
    landing_rule: str,
) -> list[Motion]:
    """Perlin noise [Per95] on the rotations of the examples concatenated in random order, one
    motion per amplitude (rad): the same order and the same noise, scaled, so that the
    amplitudes differ in nothing else."""
    order = rng.integers(0, clips.n_clips, size=n_clips)
    rt = realtime_clips(clips.rotations[order], clips.key_times[order], clips.reference_keys, clips.fps)
    rot, _ = stitch(rt, landing_rule=landing_rule)
    seed = int(rng.integers(2**31))
    return [
        solver.motion(add_rotation_noise(rot, clips.fps, a, frequency_hz, seed=seed), clips.fps) for a in amplitudes
    ]


def example_pose_sequences(clips: ClipSet) -> list[np.ndarray]:
    """The examples in real time, as rotation sequences (T_i, J, 4)."""
    return [r for r, _ in realtime_clips(clips.rotations, clips.key_times, clips.reference_keys, clips.fps)]


def gplvm_sequence(
    gplvm: BayesianGPLVM,
    codec: PoseCodec,
    n_frames: int,
    n_turns: float,
    solver: RootSolver,
    fps: float,
    phase: float = 0.0,
    radius_scale: float = 1.0,
) -> Motion:
    """GPLVM [Law03]: poses along a helix in its latent space (Sec. 7.4)."""
    path = helix_trajectory(gplvm.latent_mean_, n_frames, n_turns, phase, radius_scale)
    return solver.motion(codec.decode(gplvm.predict(path)), fps)


def dbn_sequence(
    dbn: LauDBN, codec: PoseCodec, n_frames: int, solver: RootSolver, fps: float, rng: np.random.Generator
) -> Motion:
    """DBN [LBJK09]: the transition network unrolled for n_frames frames. When the
    unrolled process diverges (a tangent vector beyond pi, i.e. no rotation any more, or
    not finite) the motion stops at the last valid frame: callers compare its length with
    the requested one."""
    vectors = dbn.sample(n_frames, rng)
    bad = ~np.all(np.isfinite(vectors) & (np.abs(vectors) < np.pi), axis=1)
    stop = int(np.argmax(bad)) if bad.any() else n_frames
    return solver.motion(codec.decode(vectors[: max(stop, 4)]), fps)


def method_sequences(
    examples: ClipSet, groups: Mapping[str, np.ndarray], solver: RootSolver, settings: Ma2010Settings
) -> dict[str, list[Motion]]:
    """Sec. 7.4: ``settings.sec7_4.sequences`` sequences of about
    ``settings.sec7_4.seconds`` s per method and setting (key of :func:`method_variants`
    -> list of Motion, in that order), every method learning from the same ``examples``: ours
    (the model of Sec. 5-6 with ``settings`` structure and variogram, xi sampled once per
    sequence or per cycle: ``sec7_4.xi``), Perlin noise (each of
    ``perlin_amplitude_sweep_rad``, ``perlin_frequency_hz``) on the examples concatenated in
    random order, the Bayesian GPLVM (``gplvm_latent_dim``, ``gplvm_iterations``; every
    ``gplvm_frame_step``-th example pose) along a helix, RBF and style-only Kriging at the
    examples' mean style, and the DBN (each of ``dbn_max_parents_sweep``) unrolled (both pose
    models on :class:`PoseCodec` vectors). Clip-based methods land their transitions by
    ``sec7_4.landing`` (:func:`.postprocess.landing_frame`). Sequence ``s`` draws from
    ``numpy.random.default_rng([seed, s])``; the settings of a swept method share its draws."""
    five, k, seconds, seed = examples, settings.sec7_4.sequences, settings.sec7_4.seconds, settings.seed
    xi_per, landing_rule = settings.sec7_4.xi, settings.sec7_4.landing
    fps = five.fps
    style = five.style.mean(axis=0)
    n_clips = clips_for_duration(five, seconds)
    n_frames = int(round(seconds * fps)) + 1
    ours = style_variation_model(groups, settings.model.structure, settings).fit(five)
    krig = mk05_kriging(settings).fit(five)
    rbf = rose98_rbf(settings).fit(five)
    seqs = example_pose_sequences(five)
    codec = PoseCodec().fit(np.concatenate(seqs))
    gplvm = BayesianGPLVM(
        settings.sec7_4.gplvm_latent_dim, max_iter=settings.sec7_4.gplvm_iterations, random_state=seed
    ).fit(np.concatenate([codec.encode(r) for r in seqs])[:: settings.sec7_4.gplvm_frame_step])
    dbns = {p: LauDBN(p).fit([codec.encode(r) for r in seqs]) for p in settings.sec7_4.dbn_max_parents_sweep}
    turns = seconds / float(np.mean(five.key_times[:, -1]))
    amplitudes = settings.sec7_4.perlin_amplitude_sweep_rad
    out: dict[str, list[Motion]] = {v: [] for v in method_variants(settings)}
    for s in range(k):  # n_sequences sequences per method
        rng = np.random.default_rng([seed, s])
        out["ours"].append(
            covering(lambda n, r: ours_sequence(ours, style, n, solver, r, xi_per, landing_rule), n_clips, seconds, rng)
        )
        noisy = perlin_sequences(
            five, n_clips, solver, rng, amplitudes, settings.sec7_4.perlin_frequency_hz, landing_rule
        )
        for a, m in zip(amplitudes, noisy):
            out[f"perlin_{a:g}"].append(trim(m, seconds))
        out["gplvm"].append(
            gplvm_sequence(
                gplvm,
                codec,
                n_frames,
                turns,
                solver,
                fps,
                phase=2 * np.pi * s / k,
                radius_scale=float(rng.uniform(0.9, 1.1)),
            )
        )
        out["rbf"].append(trim(interpolation_sequence(rbf, style, n_clips, solver, fps, landing_rule), seconds))
        out["kriging"].append(trim(interpolation_sequence(krig, style, n_clips, solver, fps, landing_rule), seconds))
        dbn_seed = int(rng.integers(2**31))
        for p, dbn in dbns.items():
            out[f"dbn_{p}"].append(dbn_sequence(dbn, codec, n_frames, solver, fps, np.random.default_rng(dbn_seed)))
    return out


@dataclass(frozen=True)
class NaturalnessReference:
    """What the naturalness measures compare with: the training poses (pose features) and
    how far a walker left out of them stands from them (``held_out_pose_distance``, cm:
    :func:`held_out_pose_distance`); the root solver whose feet (ankle and toe of each) and
    planted heights locate the feet's contact points, for foot skating; the foot joints with
    the height of each when planted (its 5th height percentile over the examples) and the
    height tolerance above it, for the earlier height-threshold measure; and the
    acceleration above which a frame counts as a discontinuity."""

    poses: np.ndarray
    solver: RootSolver
    foot_joints: np.ndarray
    foot_floor: np.ndarray
    contact_height: float
    acceleration_threshold: float
    held_out_pose_distance: float
    held_out_pose_spread: float

    @classmethod
    def from_examples(
        cls, motions: Sequence[Motion], solver: RootSolver, contact_height: float, threshold_factor: float
    ) -> "NaturalnessReference":
        """From two or more (root-solved) example motions: their poses, their feet's planted
        heights, ``threshold_factor`` times the largest joint acceleration in them, the
        held-out pose distance (the mean over examples) and its spread (the largest log-ratio
        of one example's held-out distance to that mean: how far the reference itself moves
        with the example left out)."""
        positions = [m.positions() for m in motions]
        foot_joints = np.asarray(solver.feet).reshape(-1)
        features = [pose_features(p) for p in positions]
        heights = np.concatenate([p[:, foot_joints, 1] for p in positions])
        peak = max(float(peak_acceleration(p, m.fps).max()) for p, m in zip(positions, motions))
        held_out = held_out_pose_distances(features)
        return cls(
            np.concatenate(features),
            solver,
            foot_joints,
            np.percentile(heights, 5, axis=0),
            contact_height,
            threshold_factor * peak,
            float(held_out.mean()),
            float(np.log(held_out.max() / held_out.mean())),
        )


def held_out_pose_distances(examples: Sequence[np.ndarray]) -> np.ndarray:
    """Each example's mean nearest-pose distance (cm, RMS per joint) to the poses of the others
    (pose features, :func:`..metrics.pose_distance.pose_features`; two or more examples)."""
    if len(examples) < 2:
        raise ValueError(f"held_out_pose_distance: need poses of 2 or more examples; got {len(examples)}")
    others = [np.concatenate([e for j, e in enumerate(examples) if j != i]) for i in range(len(examples))]
    return np.array([nearest_pose_distance(e, o).mean() for e, o in zip(examples, others)])


def held_out_pose_distance(examples: Sequence[np.ndarray]) -> float:
    """How far a new walker's poses stand from the examples': the mean over examples of
    :func:`held_out_pose_distances`."""
    return float(np.mean(held_out_pose_distances(examples)))


NATURALNESS_MEASURES = (
    "jerk_cm_s3",
    "root_free_jerk_cm_s3",
    "foot_skating_cm_s",
    "contact_share",
    "low_joint_speed_cm_s",
    "pose_distance_cm",
    "discontinuities_per_min",
)


def naturalness(motion: Motion, ref: NaturalnessReference) -> dict[str, float]:
    """Jerk (cm/s^3) of the whole body and root-free (:func:`..metrics.jerk.root_free_jerk`),
    foot skating (cm/s: speed of each foot's contact point while the project's contact
    detection has it on the ground, :func:`..metrics.foot_skating.foot_skating`; a foot
    sliding faster than that detection's speed limit, 50 cm/s, reads as lifted), the share
    of frames with a foot in contact (a walk has one at all times: a low share flags feet
    that float or slide fast), the earlier height-threshold measure (cm/s: horizontal speed
    of foot joints within ``contact_height`` of their planted height, heel and toe roll
    included), mean distance to the nearest training pose (cm, RMS per joint) and
    discontinuities per minute."""
    pos = motion.positions()
    solver = ref.solver
    feet = pos[:, solver.feet]  # (T, 2, F, 3)
    contacts = foot_contacts(motion, solver.feet, pos)
    low = pos[:, ref.foot_joints].copy()
    low[..., 1] -= ref.foot_floor
    minutes = motion.duration / 60.0
    return {
        "jerk_cm_s3": mean_jerk(pos, motion.fps),
        "root_free_jerk_cm_s3": root_free_jerk(pos, motion.fps),
        "foot_skating_cm_s": foot_skating(feet, contacts, motion.fps, solver.planted),
        "contact_share": float(contacts.any(axis=1).mean()),
        "low_joint_speed_cm_s": low_joint_speed(low, motion.fps, ref.contact_height),
        "pose_distance_cm": float(nearest_pose_distance(pose_features(pos), ref.poses).mean()),
        "discontinuities_per_min": count_discontinuities(pos, motion.fps, ref.acceleration_threshold)
        / max(minutes, 1e-9),
    }


def variation_between(motions: Sequence[Motion]) -> float:
    """Mean pairwise pose-set distance (cm) between sequences of one method; 0 when the
    sequences are identical."""
    feats = [pose_features(m.positions()) for m in motions]
    pairs = [(i, j) for i in range(len(feats)) for j in range(i + 1, len(feats))]
    return float(np.mean([pose_set_distance(feats[i], feats[j]) for i, j in pairs])) if pairs else 0.0


NATURALNESS_SCORES = {
    "jerk_vs_examples": "|log(jerk / examples' jerk)|",
    "root_free_jerk_vs_examples": "|log(root-free jerk / examples')|",
    "foot_skating_cm_s": "foot skating (cm/s)",
    "pose_excess_vs_held_out": "max(0, log(distance to the example poses / a held-out example's))",
    "discontinuities_per_min": "discontinuities per minute",
}


def naturalness_scores(
    measures: Mapping[str, float], example_jerk: float, example_root_free_jerk: float, held_out_pose_cm: float
) -> dict[str, float]:
    """The naturalness scores of one sequence (:data:`NATURALNESS_SCORES`), each lower =
    more natural: whole-body and root-free jerk as their log-ratio to the examples' (too
    smooth is as unnatural as too jerky); the mean distance to the nearest example pose as
    its log-ratio to ``held_out_pose_cm`` (:func:`held_out_pose_distance`), counted only
    above it, so that a copy of the examples gains nothing over the poses of a new walker;
    the others as measured."""
    excess = np.log(max(measures["pose_distance_cm"], 1e-12) / held_out_pose_cm)
    return {
        "jerk_vs_examples": abs(float(np.log(measures["jerk_cm_s3"] / example_jerk))),
        "root_free_jerk_vs_examples": abs(float(np.log(measures["root_free_jerk_cm_s3"] / example_root_free_jerk))),
        "foot_skating_cm_s": measures["foot_skating_cm_s"],
        "pose_excess_vs_held_out": max(float(excess), 0.0),
        "discontinuities_per_min": measures["discontinuities_per_min"],
    }


def at_least_as_natural(
    scores: Mapping[str, Mapping[str, float]], method: str, rivals: Sequence[str]
) -> dict[str, bool]:
    """For each score, whether ``method`` is at least as good (lower) as every one of
    ``rivals``. ``scores``: method -> score name -> mean value."""
    return {k: all(scores[method][k] <= scores[r][k] for r in rivals) for k in scores[method]}
