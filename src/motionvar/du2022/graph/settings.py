"""GraphSettings: config section ``du2022_graph`` (Du 2022 ch. 4, the Morphable Graph), the one place
its defaults are written; a value the thesis gives is the default, cited where it is set.

Subsections: :class:`ModelSettings` (``du2022_graph.model``, fitting a motion primitive, Sec. 4.4.1),
:class:`SearchSettings` (``du2022_graph.search``, the tree search comparison of Fig. 4.12, Sec. 4.6.2),
:class:`DiversitySettings` (``du2022_graph.diversity``, Fig. 4.9) and :class:`SynthesisSettings`
(``du2022_graph.synthesis``, constrained synthesis and the graph walk of Fig. 4.10, Sec. 4.5,
Algorithm 1; also what ``motionvar du2022 walk`` reads back from the saved graph).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from numbers import Integral
from typing import ClassVar

from ...core.settings import Settings

#: the hand that Fig. 4.10's reach step brings to its targets (the thesis' figure shows the right)
REACH_JOINT = "right_hand"

THESIS_BUDGET = 120  # Sec. 4.6.2: "less than 120 evaluations in most cases"


@dataclass(frozen=True)
class ModelSettings(Settings):
    """Fitting one motion primitive (DTW + SFPCA + GMM chosen by BIC, Sec. 4.4.1; the fit's own
    record is :class:`~.primitive.PrimitiveOptions`).

    n_basis: B-spline basis functions per function (Sec. 3.3.3 picks it per action; no single value).
    n_components: latent dimension of the SFPCA space, capped at clips - 1 (Sec. 3.4: 20 dimensions).
    gmm_min, gmm_max: fewest and most Gaussians tried by the model selection (Eq. 4.1).
    gmm_criterion: "bic" (Sec. 4.4.1) or "aic" (DFKI's code default).
    reg_covar: GMM covariance regularisation, relative to the mean latent variance.
    sfpca_max_iter: L-BFGS-B iterations of the SFPCA function weights (Eq. 3.8); 0 keeps the start weights.
    sfpca_weight_groups: one SFPCA weight per function (thesis) or per joint (DFKI).
    sfpca_eval_frames: canonical frames at which the SFPCA objective runs FK (None: all frames).
    sfpca_eigensolver: the SFPCA objective's eigensolver (``full`` or ``tridiagonal``, as config
        ``du2022_fda.sfpca.eigensolver``; the same to rounding). ``full``: these fits are small (20
        iterations, ~10 s at full size) and Fig. 4.12's verdicts, which turn on 2-4 comparisons,
        change under the solvers' 1e-11 difference in the gradient (docs/speed.md)."""

    SECTION: ClassVar[str] = "du2022_graph.model"

    n_basis: int = 10
    n_components: int = 20
    gmm_min: int = 1
    gmm_max: int = 10
    gmm_criterion: str = "bic"
    reg_covar: float = 0.001
    sfpca_max_iter: int = 20
    sfpca_weight_groups: str = "function"
    sfpca_eval_frames: int | None = 30
    sfpca_eigensolver: str = "full"


@dataclass(frozen=True)
class SearchSettings(Settings):
    """Fig. 4.12 (Sec. 4.6.2): space-partitioning search against random sampling and brute force.

    primitives: primitives evaluated (pick_reach_dense is added where dense picks are made).
    n_samples: latent samples per primitive the trees and brute force are built over (Fig. 4.12: 10,000).
    n_queries: random constraints per constraint type and primitive (Fig. 4.12: 1,000).
    beam: candidates kept per level by the k-means tree (and the GMM and median-means trees) for every
        verdict, fixed in advance (DFKI's code default, ``n_cluster_search_candidates`` = 4 in
        morphablegraphs/motion_generator/algorithm_configuration.py; the thesis gives none).
    beams: further beams of the k-means tree measured and tabled beside it (``candidates``).
    max_evaluations: evaluation budget of the budget beam reported beside the verdict beam: the largest
        of ``candidates`` whose mean evaluations per query stay under it (Sec. 4.6.2: "less than 120").
    leaf_size: a tree node with at most this many samples is a leaf.
    n_random: samples of the random-sampling reference (Sec. 4.6.2: 100).
    joints: semantic joint of the position and orientation constraints, per primitive.
    default_joint: semantic joint of the primitives not in ``joints``.
    pose_joints: semantic joints of the pose constraints (Sec. 4.6.2: hip, shoulders, hands, feet)."""

    SECTION: ClassVar[str] = "du2022_graph.search"

    primitives: tuple[str, ...] = ("walk_leftStance", "pick_reach", "place_reach")
    n_samples: int = 10000
    n_queries: int = 1000
    beam: int = 4
    beams: tuple[int, ...] = (2, 3, 4)
    max_evaluations: float = THESIS_BUDGET
    leaf_size: int = 16
    n_random: int = 100
    joints: dict[str, str] = field(
        default_factory=lambda: {
            "walk_leftStance": "left_ankle",
            "pick_reach": "right_hand",
            "place_reach": "right_hand",
            "pick_reach_dense": "right_hand",
        }
    )
    default_joint: str = "right_hand"
    pose_joints: tuple[str, ...] = (
        "hips",
        "left_shoulder",
        "right_shoulder",
        "left_hand",
        "right_hand",
        "left_ankle",
        "right_ankle",
    )

    def __post_init__(self) -> None:
        beams = tuple(self.beams)
        if not beams or any(isinstance(b, bool) or not isinstance(b, Integral) or b < 1 for b in beams):
            raise ValueError(f"du2022_graph.search.beams: a non-empty list of beams >= 1; got {list(self.beams)}")
        if isinstance(self.beam, bool) or not isinstance(self.beam, Integral) or self.beam < 1:
            raise ValueError(f"du2022_graph.search.beam: an integer >= 1; got {self.beam!r}")
        if not self.max_evaluations > 0:
            raise ValueError(f"du2022_graph.search.max_evaluations must be > 0; got {self.max_evaluations}")
        object.__setattr__(self, "beams", tuple(int(b) for b in beams))

    @property
    def candidates(self) -> tuple[int, ...]:
        """The beams the k-means tree runs at: ``beams`` and the verdict ``beam``, sorted."""
        return tuple(sorted(set(self.beams + (int(self.beam),))))

    def joint(self, primitive: str) -> str:
        """The semantic joint of ``primitive``'s position and orientation constraints."""
        return self.joints.get(primitive, self.default_joint)


@dataclass(frozen=True)
class DiversitySettings(Settings):
    """Fig. 4.9: kernel densities of end effectors of random samples against the training data.

    n_samples: random motions per primitive (Sec. 4.6.1: 60,000).
    level: probability mass of the samples' highest-density region used for coverage.
    coverage_threshold: coverage every projection must reach for the claim (a perfect model reaches about level).
    grid: grid cells per axis of the binned kernel density."""

    SECTION: ClassVar[str] = "du2022_graph.diversity"

    n_samples: int = 60000
    level: float = 0.95
    coverage_threshold: float = 0.9
    grid: int = 128


@dataclass(frozen=True)
class SynthesisSettings(Settings):
    """Fig. 4.10 and the graph walk (Sec. 4.5, Algorithm 1): path following and reaching, each
    step seeded by the k-means tree and optimised on Eq. 4.9; the settings of
    :func:`~.morphable_graph.follow_path` and of ``motionvar du2022 walk``.

    path: floor path (x, z) in cm that the Fig. 4.10 walk follows.
    reach_primitive: primitive of the reaching targets.
    reach_targets: number of reaching targets (training end positions of the hand, shifted).
    reach_offset_cm: shift (cm) of each reaching target from a training hand position, in a random direction;
        a target is kept only inside the variation range (a natural sample of ``reach_range_samples`` ends with
        the hand within the reach claim's bound of it).
    reach_range_samples: GMM samples of the reaching primitive whose hand end positions make its reachable
        area (Sec. 4.6.1: "the diversity of generated motions ... defines a reachable area") and whose
        log-likelihoods are the reference of a natural reach.
    tree_samples: latent samples of the k-means tree that seeds the optimisation (Sec. 4.4.2: 10,000).
    beam: tree-search candidates per level.
    likelihood_weight: weight of the negative log-likelihood in the MAP residuals (Eq. 4.9).
    method: scipy least_squares method, "lm" (Levenberg-Marquardt, Sec. 4.5.3) or "trf".
    max_nfev: most residual evaluations of one step's optimisation.
    max_steps: most steps of the path-following graph walk.
    look_ahead: steps T looked ahead (Sec. 4.5.1, no value given): the next primitive is the first of
        the T planned steps whose mean motions fit the path best; 1 is the best single transition.
    receding_horizon: our addition, not the thesis': for T > 1 each step's latent vector is optimised
        together with the T - 1 planned after it and only the step itself kept (false: the step is
        optimised on its own constraints, Algorithm 1 lines 5-6).
    joint_steps: Algorithm 1 line 9, the last steps of the walk optimised together after it: "all"
        (Algorithm 1, "optimize all steps"), a number (DFKI 4) or 0 (left out).
    joint_method: least_squares method of the joint optimisations of several steps: "lm" (MINPACK,
        as DFKI's leastsq) or "trf".
    joint_max_nfev: most residual evaluations of one joint optimisation of several steps.
    compare_variants: also make the greedy walk (T = 1, no line 9) and the receding-horizon walk for Fig. 4.10's
        table and figure.

    The walk's start, stepping and end nodes (``start``, ``cyclic``, ``end``) are the primitive
    names of the prep stage, not config keys."""

    SECTION: ClassVar[str] = "du2022_graph.synthesis"
    start: ClassVar[str] = "walk_start"
    end: ClassVar[str] = "walk_end"
    cyclic: ClassVar[tuple[str, ...]] = ("walk_leftStance", "walk_rightStance")

    path: tuple[tuple[float, float], ...] = ((0, 0), (300, 0), (450, 150), (450, 350))
    reach_primitive: str = "pick_reach"
    reach_targets: int = 5
    reach_offset_cm: float = 15.0
    reach_range_samples: int = 10000
    tree_samples: int = 10000
    beam: int = 2
    likelihood_weight: float = 1.0
    method: str = "lm"
    max_nfev: int = 100
    max_steps: int = 30
    look_ahead: int = 2
    receding_horizon: bool = False
    joint_steps: int | str = "all"
    joint_method: str = "lm"
    joint_max_nfev: int = 100
    compare_variants: bool = True

    def __post_init__(self) -> None:
        if int(self.look_ahead) < 1:
            raise ValueError(f"du2022_graph.synthesis.look_ahead must be >= 1; got {self.look_ahead}")
        if int(self.reach_range_samples) < 100:
            raise ValueError(
                f"du2022_graph.synthesis.reach_range_samples must be >= 100; got {self.reach_range_samples}"
            )
        js = self.joint_steps
        if not (js == "all" or (isinstance(js, Integral) and not isinstance(js, bool) and js >= 0)):
            raise ValueError(f"du2022_graph.synthesis.joint_steps: 'all' or an integer >= 0; got {js!r}")
        for key in ("method", "joint_method"):
            if getattr(self, key) not in ("lm", "trf"):
                raise ValueError(f"du2022_graph.synthesis.{key} must be 'lm' or 'trf'; got {getattr(self, key)!r}")


@dataclass(frozen=True)
class GraphSettings(Settings):
    """Config section ``du2022_graph`` (Du 2022 ch. 4).

    seed: seed of every random draw (GMM fits, samples, constraints, trees).
    primitives: primitives of the prep stage modelled as nodes of the graph (each needs >= 3 clips).
    dense_picks_per_subject: dense-grid picks per synthetic subject for the synthetic picking
        primitive of Fig. 4.11 (model pick_reach_dense; 0 leaves it out).
    dense_grid_spacing_cm: node spacing (cm) of the generator's dense target grid.
    model, search, diversity, synthesis: the subsections (module docstring)."""

    SECTION: ClassVar[str] = "du2022_graph"

    seed: int = 0
    primitives: tuple[str, ...] = (
        "walk_start",
        "walk_leftStance",
        "walk_rightStance",
        "walk_end",
        "sidestep",
        "pick_reach",
        "pick_retrieve",
        "place_reach",
        "place_retrieve",
    )
    dense_picks_per_subject: int = 4
    dense_grid_spacing_cm: float = 10.0
    model: ModelSettings = field(default_factory=ModelSettings)
    search: SearchSettings = field(default_factory=SearchSettings)
    diversity: DiversitySettings = field(default_factory=DiversitySettings)
    synthesis: SynthesisSettings = field(default_factory=SynthesisSettings)
