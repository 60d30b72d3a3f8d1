"""Egges2004Settings: config section ``egges2004`` (Egges, Molet, Magnenat-Thalmann 2004), the
one place its defaults are written; ``config/schema.yaml`` repeats them for the reader.

The paper gives almost no numbers: where it names a value (three resting categories,
Sec. 5.1; metres for the root translation, H-Anim, Sec. 3.2) that is the default, every
other default is this project's choice, written with its reason. Rule scripts build the
settings from the section and pass them whole (``Egges2004Settings.from_dict``).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..core.settings import Settings

HELD_OUT_BY = ("clips", "time")


@dataclass(frozen=True)
class AnalysisSettings(Settings):
    """Building one person's database from their recordings (Sec. 5.1-5.3, 6.1-6.2).

    smooth_s: Gaussian smoothing (s) of the PC curves before the posture speed.
    rest_speed: posture-speed threshold (Eq. 4 units per second) below which a frame
        rests; None picks it per person as the boundary of a two-component Gaussian
        mixture of log speeds (rest vs shift).
    min_rest_s: shortest resting segment (s).
    min_shift_rms: a gap between two resting segments is a balance shift only if the mean
        postures on both sides differ by this many times the resting sway RMS (Eq. 4
        metric); otherwise the segments are joined.
    max_categories: k of the k-means on resting postures, the most categories: Sec. 5.1
        names three (balance on the left foot, on the right foot, on both feet).
    support_margin: margin around 0.5 of the support ratio for naming left / right / both.
    variation_pcs: leading PCs that get small variations (Sec. 6.2: "a subset of PC values").
    extrema_eps_sd: extremum error epsilon (Sec. 6.2) in standard deviations of the PC's
        resting variation.
    variation_clusters: k of the k-means on (distance, value) pairs, per PC (Sec. 6.2).
    """

    SECTION = "egges2004.analysis"

    smooth_s: float = 0.15
    rest_speed: float | None = None
    min_rest_s: float = 1.0
    min_shift_rms: float = 5.0
    max_categories: int = 3
    support_margin: float = 0.1
    variation_pcs: int = 10
    extrema_eps_sd: float = 0.5
    variation_clusters: int = 6


@dataclass(frozen=True)
class IdentificationSettings(Settings):
    """Person identification (Sec. 5.6, 8) by a classifier on windows of idle motion.

    window_s: length (s) of the non-overlapping windows the classifier sees.
    feature_pcs: leading PCs whose window mean and SD are features.
    generated_s: seconds of idle motion generated per subject (and of the Perlin baseline).
    alpha: significance level of each test of the claim: accuracy against chance (1/N) with all
        and with movement-only features (binomial), generated against Perlin (paired, McNemar).
    min_power: the power a binomial test against chance must have, with the generated windows, to
        detect a classifier as accurate as on the held-out recordings; a test below it that fails
        makes the claim not testable (too few windows to tell), not failed.
    """

    SECTION = "egges2004.identification"

    window_s: float = 20.0
    feature_pcs: int = 8
    generated_s: float = 120.0
    alpha: float = 0.01
    min_power: float = 0.8


@dataclass(frozen=True)
class RepetitionSettings(Settings):
    """Repetition (Sec. 6.2) as the best normalised cross-correlation between windows, and
    structure as the spectral distance of the variations from the recorded ones.

    sequence_s: length (s) of the generated, looped, white-noise and Perlin sequences.
    window_s: window length (s), also of the Welch segments of the spectra; Sec. 6.2 gives
        none: 5 s gives each of the ~20-s recorded rests per subject two windows or more.
    stride_s: step (s) between the candidate windows compared with each window.
    fps: frame rate (Hz) the sequences are subsampled to before comparing.
    loop_clip_s: length (s) of the recorded clip that is looped.
    tolerance: relative margin of the repetition claim: generated variations must repeat more
        than this much less than the looped clip, and at most this much more than the recorded
        rest variations (at the recorded length) to reproduce it.
    subjects: subjects evaluated (the first ones); 0 = all.
    """

    SECTION = "egges2004.repetition"

    sequence_s: float = 300.0
    window_s: float = 5.0
    stride_s: float = 0.1
    fps: float = 20.0
    loop_clip_s: float = 30.0
    tolerance: float = 0.1
    subjects: int = 0


@dataclass(frozen=True)
class FittingSettings(Settings):
    """Animation fitting (Sec. 5.4.4, 7.1).

    pairs: random (p, q) posture pairs fitted per subject and ramp (a tenth of it for
        idle_between).
    sequence_s: length (s) of the balance sequences whose junctions are checked.
    between_s: length (s) of the idle motion between two given postures (Sec. 7.1).
    quantile: quantile of the frame-to-frame steps inside recorded shifts that a junction
        step must not exceed.
    """

    SECTION = "egges2004.fitting"

    pairs: int = 50
    sequence_s: float = 120.0
    between_s: float = 20.0
    quantile: float = 0.99


@dataclass(frozen=True)
class SpeedSettings(Settings):
    """Generation speed (Sec. 8: "generated and played in real-time").

    sequence_s: length (s) of each timed sequence.
    repeats: timed runs per subject; their mean time counts.
    subjects: subjects timed (the first ones); 0 = all.
    """

    SECTION = "egges2004.speed"

    sequence_s: float = 300.0
    repeats: int = 3
    subjects: int = 3


@dataclass(frozen=True)
class AnimationSettings(Settings):
    """The GIF of generated idle motion (rule egges2004_animation; Fig. 10).

    seconds: length (s) of the generated motion shown.
    fps: frames per second of the GIF.
    panel_px: width and height (pixels) of one subject's panel.
    """

    SECTION = "egges2004.animation"

    seconds: float = 12.0
    fps: float = 15
    panel_px: int = 220


@dataclass(frozen=True)
class Egges2004Settings(Settings):
    """Config section ``egges2004``: posture PCA, one idle database per subject and the
    evaluations of Sec. 5.4.4 (fitting), 6 (repetition) and 8 (identification, speed).

    seed: seed of every random draw (categories' k-means, generation, baselines, classifier).
    held_out_by: what is held out of the databases, for identification: ``"clips"``, the last
        ``held_out_clips`` clips of each subject (by clip_id; a subject with no more clips than
        that is left out); ``"time"``, the last ``held_out_fraction`` of every idle recording's
        frames, so that one long recording per person serves (the paper builds a person's
        database from "one or more recorded animations", Sec. 5.6).
    held_out_clips: idle clips per subject held out (``held_out_by: clips``).
    held_out_fraction: share of every recording held out at its end (``held_out_by: time``).
    held_out_search_s: the cut falls at the rest (the pelvis's slowest second) within this many
        seconds of that share, so that no balance shift is cut in two.
    translation_scale: factor on the root translation (cm) in the posture vectors: 0.01
        gives metres, the H-Anim unit of the paper's skeleton (Sec. 3.2).
    perlin_frequency_hz: lattice frequency (Hz) of the Perlin-noise-on-PCs baseline; set by
        hand, as Sec. 6 says such noise must be.
    figure_subjects: subjects shown in the category-graph and extrema figures and the GIF.
    extrema_pc: the principal component (1 = first) whose curve and extrema are drawn
        (Fig. 7-8).
    """

    SECTION = "egges2004"

    seed: int = 0
    held_out_by: str = "clips"
    held_out_clips: int = 1
    held_out_fraction: float = 0.3
    held_out_search_s: float = 3.0
    translation_scale: float = 0.01
    perlin_frequency_hz: float = 0.5
    figure_subjects: int = 3
    extrema_pc: int = 1
    analysis: AnalysisSettings = field(default_factory=AnalysisSettings)
    identification: IdentificationSettings = field(default_factory=IdentificationSettings)
    repetition: RepetitionSettings = field(default_factory=RepetitionSettings)
    fitting: FittingSettings = field(default_factory=FittingSettings)
    speed: SpeedSettings = field(default_factory=SpeedSettings)
    animation: AnimationSettings = field(default_factory=AnimationSettings)

    def __post_init__(self) -> None:
        if self.held_out_by not in HELD_OUT_BY:
            raise ValueError(f"egges2004.held_out_by must be one of {list(HELD_OUT_BY)}; got {self.held_out_by!r}")
        if not 0.0 < self.held_out_fraction < 1.0:
            raise ValueError(f"egges2004.held_out_fraction must lie in (0, 1); got {self.held_out_fraction}")
