"""The hierarchical model (Ma et al. 2010, Sec. 5-6.2): joint groups, latent variation
parameters, the parameter propagation network and one style-and-variation interpolation
(SVI) per joint group.

Eq. 11: M^I(c) = m_s^I(c) + m_v^I(xi_I) + sum_i lambda_i^I([c, xi_I]) r_i^I, with the two
trend hyperplanes of Eq. 12-13 fitted together by least squares (their constants
alpha_0 and beta_0 are not separately identifiable and merge into one intercept) and the
weights from universal Kriging over [c, xi_I] (:mod:`.kriging`). Whole clips are the units
(Sec. 6.2). The group that the network attaches to c (legs, in the lower-first structure)
also carries the clip's key times (for the inverse time warp) and, for behaviours with
flight phases, the root height curve (Sec. 6.3).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from ..core.kinematics import fk
from .keyframes import keyframe_signal
from .kriging import UniversalKriging
from .network import LOWER_FIRST, STYLE, UPPER_FIRST, PropagationNetwork, choose_structure
from .representation import ClipCodec, ClipSet
from .settings import Ma2010Settings, ModelSettings
from .variation import determinative_joints, joint_importance, joint_variation, latent_variation

GROUP_ORDER = ("legs", "left_arm", "right_arm", "upper_body")  # A, B, C, D (Fig. 4)


@dataclass
class ClipPrediction:
    """Synthesized clips on the common timeline: rotations (M, T, J, 4), key times (M, K)
    in seconds, and the root height curve (M, T) when the model predicts one."""

    rotations: np.ndarray
    key_times: np.ndarray
    root_height: np.ndarray | None = None

    def __len__(self) -> int:
        return self.rotations.shape[0]


def check_groups(groups: Mapping[str, np.ndarray], n_joints: int) -> dict[str, np.ndarray]:
    """The four joint groups of Fig. 4 (legs, left arm, right arm, upper body) must
    partition the skeleton's joints."""
    missing = [g for g in GROUP_ORDER if g not in groups]
    if missing:
        raise ValueError(f"joint groups {missing} missing (need {list(GROUP_ORDER)})")
    allj = np.concatenate([np.asarray(groups[g], dtype=np.int64) for g in GROUP_ORDER])
    if len(allj) != n_joints or not np.array_equal(np.sort(allj), np.arange(n_joints)):
        raise ValueError(f"joint groups must partition the {n_joints} joints exactly once")
    return {g: np.asarray(groups[g], dtype=np.int64) for g in GROUP_ORDER}


def structure_evidence(clips: ClipSet, groups: Mapping[str, np.ndarray]) -> tuple[float, float]:
    """D_l and D_u (Eq. 3) over all the examples' frames, for the "auto" structure (Fig. 5):
    the root-square sum over clips of each clip's D_l and D_u, with the lower body the
    legs group and the upper body every other joint (Sec. 4.1)."""
    sk = clips.skeleton
    lower = np.asarray(groups["legs"], dtype=np.int64)
    upper = np.setdiff1d(np.arange(sk.n_joints), lower)
    d_l = d_u = 0.0
    for rot in clips.rotations:  # loop over clips
        sig = keyframe_signal(fk(rot, np.zeros((len(rot), 3)), sk.offsets, sk.parents), lower, upper)
        d_l, d_u = d_l + sig.d_lower**2, d_u + sig.d_upper**2
    return float(np.sqrt(d_l)), float(np.sqrt(d_u))


def resolve_structure(
    structure: str | Mapping[str, tuple[str, ...]], clips: ClipSet, groups: Mapping[str, np.ndarray]
) -> str | Mapping[str, tuple[str, ...]]:
    """``structure`` with "auto" resolved on ``clips`` (Fig. 5: "lower_first" when D_l >=
    D_u, else "upper_first"); anything else unchanged. For protocols that fit many models
    to subsets of one example set (leave-one-out) with the structure of the whole set."""
    if not isinstance(structure, str) or structure != "auto":
        return structure
    d_l, d_u = structure_evidence(clips, groups)
    return "lower_first" if d_l >= d_u else "upper_first"


class StyleVariationModel:
    """Ma et al. 2010's model of style and variation for one behaviour.

    Args:
        groups: joint group name -> joint indices (``JointMap.group_indices``).
        structure: "auto" (Fig. 5 by D_l vs D_u: given to :meth:`fit`, else measured on
            its examples by :func:`structure_evidence`), "lower_first", "upper_first", or an
            explicit parent mapping.
        variogram_model, variogram_scale: the variogram of each group's Kriging, see
            :mod:`.kriging` (config ma2010.model.variogram_model, variogram_scale).
        flight: predict the root height curve (behaviours with flight phases, Sec. 6.3).
        trend_rcond: relative cut-off of the pseudo-inverse of each group's Kriging trend
            (Eq. 12-13; :class:`.kriging.UniversalKriging`); 0 is the literal fit.
        key_timing: how the key times are interpolated (:data:`.settings.KEY_TIMINGS`).
    """

    def __init__(
        self,
        groups: Mapping[str, np.ndarray],
        structure: str | Mapping[str, tuple[str, ...]],
        variogram_model: str,
        flight: bool = False,
        n_bins: int | None = None,
        *,
        variogram_scale: str,
        trend_rcond: float = 0.0,
        key_timing: str = ModelSettings.key_timing,
    ):
        self.groups = {g: np.asarray(v, dtype=np.int64) for g, v in groups.items()}
        self.trend_rcond = trend_rcond
        self.key_timing = key_timing
        self.structure = structure
        self.variogram_model = variogram_model
        self.variogram_scale = variogram_scale
        self.flight = flight
        self.n_bins = n_bins

    def _structure(self, clips: ClipSet, d_lower: float | None, d_upper: float | None) -> dict[str, tuple[str, ...]]:
        if isinstance(self.structure, Mapping):
            return dict(self.structure)
        if self.structure == "lower_first":
            return dict(LOWER_FIRST)
        if self.structure == "upper_first":
            return dict(UPPER_FIRST)
        if self.structure == "auto":
            if d_lower is None or d_upper is None:
                d_lower, d_upper = structure_evidence(clips, self.groups)
            return choose_structure(d_lower, d_upper)
        raise ValueError(f"StyleVariationModel: unknown structure {self.structure!r}")

    def fit(self, clips: ClipSet, d_lower: float | None = None, d_upper: float | None = None) -> "StyleVariationModel":
        """Learn tau (Eq. 7-9), the network (Eq. 10) and the four SVIs (Eq. 11-13).
        ``d_lower``/``d_upper`` (Eq. 3) choose the "auto" structure; without them they
        are measured on ``clips`` (:func:`structure_evidence`)."""
        self.groups = check_groups(self.groups, clips.skeleton.n_joints)
        if clips.n_clips < 2:
            raise ValueError(f"StyleVariationModel.fit: need at least 2 example clips, got {clips.n_clips}")
        delta = joint_variation(clips.rotations)
        self.eta_ = joint_importance(delta)
        self.tau_ = determinative_joints(self.eta_, self.groups)
        xi = latent_variation(delta, self.tau_)
        self.xi_ = {g: xi[:, k] for k, g in enumerate(self.tau_)}
        structure = self._structure(clips, d_lower, d_upper)
        self.network_ = PropagationNetwork(structure).fit(clips.style, self.xi_)
        self.timing_group_ = next(g for g, pa in structure.items() if STYLE in pa)
        self.n_keys_ = len(clips.reference_keys)
        self.reference_keys_ = clips.reference_keys
        self.skeleton_ = clips.skeleton
        self.fps_ = clips.fps
        self.style_ = clips.style
        self.key_times_span_ = clips.key_times[:, -1] - clips.key_times[:, 0]
        self.interpolators_: dict[str, tuple[ClipCodec, UniversalKriging]] = {}
        for g, joints in self.groups.items():
            lead = g == self.timing_group_
            codec = ClipCodec(joints, timing=lead, root_height=lead and self.flight, key_timing=self.key_timing).fit(
                clips
            )
            x = np.concatenate([clips.style, self.xi_[g][:, None]], axis=1)
            krig = UniversalKriging(
                self.variogram_model, self.n_bins, variogram_scale=self.variogram_scale, trend_rcond=self.trend_rcond
            )
            krig = krig.fit(x, codec.encode(clips))
            self.interpolators_[g] = (codec, krig)
        return self

    def sample_variation(
        self,
        c: np.ndarray,
        rng: np.random.Generator | None = None,
        fixed: Mapping[str, float] | None = None,
        noise: bool = True,
    ) -> dict[str, np.ndarray]:
        """xi of every group for style parameters c (M, d) from the network (Eq. 10)."""
        return self.network_.sample(np.atleast_2d(c), rng=rng, fixed=fixed, noise=noise)

    def predict(self, c: np.ndarray, xi: Mapping[str, np.ndarray]) -> ClipPrediction:
        """Clips for style parameters c (M, d) and latent variation xi (group -> (M,)),
        assembled from the four partial motions (Eq. 11)."""
        c = np.atleast_2d(np.asarray(c, dtype=float))
        M = len(c)
        T = self.reference_keys_[-1].astype(int) + 1
        rotations = np.zeros((M, int(T), self.skeleton_.n_joints, 4))
        keys = height = None
        for g, (codec, krig) in self.interpolators_.items():
            x = np.concatenate([c, np.broadcast_to(np.asarray(xi[g], dtype=float), (M,))[:, None]], axis=1)
            rot, k, h = codec.decode(krig.predict(x), self.n_keys_)
            rotations[:, :, codec.joints] = rot
            keys = k if k is not None else keys
            height = h if h is not None else height
        return ClipPrediction(rotations=rotations, key_times=keys, root_height=height)

    def synthesize_clips(
        self,
        c: np.ndarray,
        rng: np.random.Generator | None = None,
        fixed: Mapping[str, float] | None = None,
        noise: bool = True,
    ) -> tuple[ClipPrediction, dict[str, np.ndarray]]:
        """Sample xi given c (Eq. 10), then predict the clips (Eq. 11)."""
        xi = self.sample_variation(c, rng=rng, fixed=fixed, noise=noise)
        return self.predict(c, xi), xi


def style_variation_model(
    groups: Mapping[str, np.ndarray], structure: str | Mapping[str, tuple[str, ...]], settings: Ma2010Settings
) -> StyleVariationModel:
    """An unfitted :class:`StyleVariationModel` on ``groups`` with ``structure`` and the variogram,
    trend cut-off and key timing of ``settings`` (config ma2010.model.variogram_model, variogram_scale,
    trend_rcond, key_timing)."""
    return StyleVariationModel(
        groups,
        structure,
        settings.model.variogram_model,
        variogram_scale=settings.model.variogram_scale,
        trend_rcond=settings.model.trend_rcond,
        key_timing=settings.model.key_timing,
    )
