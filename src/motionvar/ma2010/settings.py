"""Ma2010Settings: config section ``ma2010``, every option of the Ma et al. 2010 rules, one
subsection per stage: the walking cycles (``clips``), the model of Sec. 5-6 (``model``) and
one per evaluation (``fig3``, ``fig6``, ``fig7b``, ``fig8``, ``sec7_4``, ``sec8``). The one
place their defaults are written: the paper's value where it gives one (cited per field),
else the project's choice; ``config/schema.yaml`` repeats them."""

from __future__ import annotations

from dataclasses import dataclass, field

from ..core.settings import Settings

STRUCTURES = ("auto", "lower_first", "upper_first")
VARIOGRAM_MODELS = ("linear", "power", "exponential", "gaussian", "spherical", "auto")
VARIOGRAM_SCALES = ("sd", "none")
ROOT_GROUPS = ("legs", "upper_body")
LOO_UNITS = ("walk", "cycle")
#: how a clip's key times are interpolated (:func:`.correspondence.encode_key_times`)
KEY_TIMINGS = ("log_intervals", "absolute")
LOO_XIS = ("mean", "sampled", "own")
XI_DRAWS = ("sequence", "clip")
LANDING_RULES = ("significant_maximum", "first_maximum")


@dataclass(frozen=True)
class ClipSettings(Settings):
    """The walking cycles (rule ma2010_clips, Sec. 4), saved with them."""

    SECTION = "ma2010.clips"

    walk_styles: tuple[str, ...] = ("neutral",)
    """Metadata styles of the walks used as examples (empty: all)."""
    walk_variants: tuple[str, ...] = ("forward",)
    """Metadata variants of the walks used as examples (empty: all)."""
    n_frames: int = 64
    """Frames of the common timeline (Sec. 4.2; the paper gives none)."""
    keyframe_prominence: float = 0.1
    """A key frame (extremum of S_M(t), Eq. 4) stands out by this fraction of the signal's range."""
    keyframe_min_separation_s: float = 0.1
    """Seconds between two key frames of the same kind, at least."""


@dataclass(frozen=True)
class ModelSettings(Settings):
    """The style-and-variation model (Sec. 5-6), in every rule that fits one."""

    SECTION = "ma2010.model"

    structure: str = "auto"
    """Parameter propagation network: "auto" is Fig. 5's rule (lower-first when D_l >= D_u, Eq. 3)."""
    variogram_model: str = "auto"
    """"auto" picks the variogram by Akaike's criterion per joint group (Sec. 6.1 inherits the
    variogram from MK05 and does not say which)."""
    variogram_scale: str = "sd"
    """"sd" weighs each output dimension by 1/its variance in the semivariance (the paper gives
    no units; "none": raw squares)."""
    trend_rcond: float = 0.0
    """The trend hyperplane (Eq. 12-13) of ours, MK05 Kriging, RBF's linear part and the
    least-squares reference drops the directions of the standardized design [1, c, xi] whose
    singular value is below this fraction of the largest. 0 is the exact least-squares fit Sec.
    6.2 asks for; with examples nearly on a line their thinnest direction is noise that Eq. 11
    extrapolates off the line (0.05-0.3 cut it)."""
    key_timing: str = "log_intervals"
    """Key times interpolated as the logarithms of the intervals between key frames
    ("log_intervals": every predicted interval is positive, so a synthesis always moves forward,
    as Sec. 4.2's incremental time warping ensures) or as absolute times ("absolute": a
    synthesis far from the examples can put a key before the one it follows, and counts as
    failed)."""
    root_group: str = "legs"
    """Joint group of the root rotation (Fig. 4 does not place it; "upper_body" is Fig. 6's ablation)."""

    def __post_init__(self) -> None:
        _check_choices(
            self,
            structure=STRUCTURES,
            variogram_model=VARIOGRAM_MODELS,
            variogram_scale=VARIOGRAM_SCALES,
            root_group=ROOT_GROUPS,
            key_timing=KEY_TIMINGS,
        )
        if not (isinstance(self.trend_rcond, (int, float)) and 0.0 <= self.trend_rcond < 1.0):
            raise ValueError(f"trend_rcond must be a number in [0, 1); got {self.trend_rcond!r}")


@dataclass(frozen=True)
class Fig3Settings(Settings):
    """Fig. 3: the key frames of S_M(t) at one gait phase."""

    SECTION = "ma2010.fig3"

    phase_sd: float = 0.05
    """Claim bound: the circular SD of the maxima's phase (ours; the paper gives none)."""
    max_clips: int = 0
    """Walks and runs examined at most; 0 = all."""


@dataclass(frozen=True)
class Fig6Settings(Settings):
    """Fig. 6: leave-one-out prediction of held-out cycles (Sec. 7.1)."""

    SECTION = "ma2010.fig6"

    max_clips: int = 0
    """Held-out cycles; 0 = every one (Sec. 7.1: "repeated until each example motion clip ...
    has been used once as the test data")."""
    unit: str = "cycle"
    """The fold: the held-out cycle alone (Sec. 7.1: "one of the example motion clips" is left
    out, a clip being a cycle here; "walk": its whole walk, siblings too)."""
    xi: str = "mean"
    """The verdict's latent variation: the network's conditional mean given the style ("mean":
    Sec. 7.1 predicts a held-out clip "according to its style parameters", and Sec. 8 generates
    xi from the style), a draw from the network ("sampled") or the held-out cycle's own xi (Eq.
    7-9, "own": knows the answer's variation). Every kind is a row of the table."""

    def __post_init__(self) -> None:
        _check_choices(self, unit=LOO_UNITS, xi=LOO_XIS)


@dataclass(frozen=True)
class Fig7bSettings(Settings):
    """Fig. 7b: the reliability of synthesis over a grid of styles."""

    SECTION = "ma2010.fig7b"

    grid: int = 15
    """Grid points per style dimension."""
    margin: float = 0.5
    """The grid extends the examples' style range by this fraction of it on each side."""


@dataclass(frozen=True)
class Fig8Settings(Settings):
    """Fig. 8: variants at one style against the examples nearest it."""

    SECTION = "ma2010.fig8"

    variants: int = 5
    """Clips shown at one style (Fig. 8a shows five; table rows, figure, stride check)."""
    draws: int = 200
    """The spread of ours is taken over this many xi draws at the style (the shown variants are
    the first); the spread of five draws is itself noise."""
    bootstrap: int = 1000
    """Resamples of the nearest examples for the interval of their spread."""
    spread_ratio_bounds: tuple[float, float] = (0.33, 3.0)
    """Claim bounds of "of the same order" (ours; the paper gives none)."""

    def __post_init__(self) -> None:
        if self.draws < self.variants:
            raise ValueError(f"draws must be at least variants = {self.variants}; got {self.draws!r}")


@dataclass(frozen=True)
class Sec74Settings(Settings):
    """Sec. 7.4: ours against Perlin noise, a DBN and a GPLVM (the paper gives no number;
    Perlin's parameters are "manually tuned")."""

    SECTION = "ma2010.sec7_4"
    RENAMED = {"perlin_amplitude_rad": "perlin_amplitude_sweep_rad", "dbn_max_parents": "dbn_max_parents_sweep"}

    examples: int = 5
    """Example cycles all methods learn from, one per subject nearest the median stride (Sec.
    7.4 uses the five example clips of Fig. 1)."""
    seconds: float = 30.0
    """Length of each synthesized sequence (s)."""
    sequences: int = 3
    """Sequences per method (Sec. 7.4 compares three)."""
    perlin_amplitude_sweep_rad: tuple[float, ...] = (0.05, 0.1, 0.2)
    """Perlin noise amplitudes per rotation axis (rad), one rival each: half, once and twice the
    project's hand-set 0.1 rad (the paper tunes its noise by hand and gives no value), fixed
    before any result; the claim holds only if it holds against each."""
    perlin_frequency_hz: float = 1.0
    """Perlin noise base frequency (Hz; two octaves)."""
    gplvm_latent_dim: int = 3
    """GPLVM latent dimensions (the helix needs 3)."""
    gplvm_iterations: int = 200
    """L-BFGS-B iterations of the (Bayesian) GPLVM."""
    gplvm_frame_step: int = 4
    """The GPLVM learns every n-th frame of the examples."""
    dbn_max_parents_sweep: tuple[int, ...] = (4, 8, 16)
    """The most parents per DOF in the DBN's networks, one rival each: half, once and twice the
    project's 8 (Lau et al. 2009 learn the structure and give no limit), fixed before any result."""
    contact_height_cm: float = 2.0
    """The height-threshold measure (table column low_joint_speed_cm_s, not a score): a foot
    joint within this height (cm) above its planted height counts."""
    xi: str = "sequence"
    """How often ours draws the latent variation xi (the paper does not say): once per sequence
    ("sequence", one person walks it) or anew for every cycle ("clip")."""
    landing: str = "significant_maximum"
    """Landing frame of the transitions (Eq. 15): the first maximum of the pose distance with a
    prominence of at least a quarter of its range ("significant_maximum") or the first local
    maximum ("first_maximum", the paper's rule read literally)."""
    discontinuity_factor: float = 1.5
    """A frame is a discontinuity when a joint accelerates more than this times the examples' peak."""
    animation_seconds: float = 3.0
    """Seconds of each method's first sequence in the GIF."""

    def __post_init__(self) -> None:
        _check_choices(self, xi=XI_DRAWS, landing=LANDING_RULES)
        _check_sweep("perlin_amplitude_sweep_rad", self.perlin_amplitude_sweep_rad, 0.0, "amplitudes (rad) >= 0")
        _check_sweep("dbn_max_parents_sweep", self.dbn_max_parents_sweep, 1, "whole numbers of parents >= 1")


@dataclass(frozen=True)
class Sec8Settings(Settings):
    """Sec. 8: the time synthesis takes (the paper: 0.15 s per s, on average)."""

    SECTION = "ma2010.sec8"

    seconds: float = 60.0
    """Seconds of motion synthesized."""
    repeats: int = 3
    """Timing repeats; their mean is reported, as the paper's "on average"."""


#: the flat keys of the section before it was nested -> their dotted key now
FLAT_KEYS = {
    **{k: f"clips.{k}" for k in ("walk_styles", "walk_variants", "n_frames", "keyframe_prominence")},
    "keyframe_min_separation_s": "clips.keyframe_min_separation_s",
    **{k: f"model.{k}" for k in ("structure", "variogram_model", "variogram_scale", "trend_rcond")},
    "key_timing": "model.key_timing",
    "root_group": "model.root_group",
    "fig3_phase_sd": "fig3.phase_sd",
    "fig3_max_clips": "fig3.max_clips",
    "loo_max_clips": "fig6.max_clips",
    "loo_unit": "fig6.unit",
    "loo_xi": "fig6.xi",
    "reliability_grid": "fig7b.grid",
    "reliability_margin": "fig7b.margin",
    "fig8_variants": "fig8.variants",
    "fig8_draws": "fig8.draws",
    "fig8_bootstrap": "fig8.bootstrap",
    "spread_ratio_bounds": "fig8.spread_ratio_bounds",
    "comparison_examples": "sec7_4.examples",
    "comparison_seconds": "sec7_4.seconds",
    "comparison_sequences": "sec7_4.sequences",
    "comparison_xi": "sec7_4.xi",
    "comparison_landing": "sec7_4.landing",
    **{
        k: f"sec7_4.{k}"
        for k in (
            "perlin_amplitude_sweep_rad",
            "perlin_frequency_hz",
            "gplvm_latent_dim",
            "gplvm_iterations",
            "gplvm_frame_step",
            "dbn_max_parents_sweep",
            "contact_height_cm",
            "discontinuity_factor",
            "animation_seconds",
        )
    },
    "perlin_amplitude_rad": "sec7_4.perlin_amplitude_sweep_rad",
    "dbn_max_parents": "sec7_4.dbn_max_parents_sweep",
    "timing_seconds": "sec8.seconds",
    "timing_repeats": "sec8.repeats",
}


@dataclass(frozen=True)
class Ma2010Settings(Settings):
    """Options of the Ma 2010 rules (config section ``ma2010``; meanings in config/schema.yaml):
    ``seed`` of every random draw (xi, fold subsets, baselines) and one subsection per stage."""

    SECTION = "ma2010"
    RENAMED = FLAT_KEYS

    seed: int = 0
    clips: ClipSettings = field(default_factory=ClipSettings)
    model: ModelSettings = field(default_factory=ModelSettings)
    fig3: Fig3Settings = field(default_factory=Fig3Settings)
    fig6: Fig6Settings = field(default_factory=Fig6Settings)
    fig7b: Fig7bSettings = field(default_factory=Fig7bSettings)
    fig8: Fig8Settings = field(default_factory=Fig8Settings)
    sec7_4: Sec74Settings = field(default_factory=Sec74Settings)
    sec8: Sec8Settings = field(default_factory=Sec8Settings)


def _check_choices(settings: Settings, **choices: tuple[str, ...]) -> None:
    """Each named field of ``settings`` is one of its allowed values."""
    for key, allowed in choices.items():
        if getattr(settings, key) not in allowed:
            raise ValueError(f"{key} must be one of {list(allowed)}; got {getattr(settings, key)!r}")


def _check_sweep(key: str, values: object, least: float, what: str) -> None:
    """A Sec. 7.4 sweep: a non-empty list of distinct ``what`` (at least ``least``)."""
    ok = isinstance(values, tuple) and len(values) > 0 and len(set(values)) == len(values)
    ok = ok and all(isinstance(v, (int, float)) and not isinstance(v, bool) and v >= least for v in values)
    if ok and isinstance(least, int):
        ok = all(isinstance(v, int) for v in values)
    if not ok:
        raise ValueError(f"{key} must be a non-empty list of distinct {what}; got {values!r}")
