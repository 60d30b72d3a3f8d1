"""FdaSettings: config section ``du2022_fda``, Du 2022 ch. 3 (Sec. 3.3): cubic B-spline functions
(Fig. 3.9), FPCA, normalized FPCA, SFPCA and a Bayesian GPLVM (Fig. 3.10, 3.11), latent
dimensions per primitive (Table 3.1). The one place where the section's defaults are written;
``config/schema.yaml`` describes every key.

One subsection class per part: :class:`BasisSettings`, :class:`ReconstructionSettings`,
:class:`SfpcaSettings`, :class:`GplvmSettings`, :class:`LatentSettings`,
:class:`TableSettings`. Where the thesis gives a value it is the default (cited below); the
thesis states no iteration count, tolerance or stopping rule for SFPCA's L-BFGS-B or for the
GPLVM, no t-SNE perplexity and no threshold for Table 3.1's dimensions.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ...core.settings import Settings


@dataclass(frozen=True)
class BasisSettings(Settings):
    """B-spline basis size (Sec. 3.3.3, Fig. 3.9).

    n_basis: candidate numbers of cubic B-spline basis functions K (ascending; Table 3.1
        chooses K = 10 to 25).
    min_relative_drop: cut-off rule: K is the smallest candidate from which on every next one
        lowers the joint-space RMSE by no more than this fraction per added basis function
        (the thesis picks "the cut-off point" without a number); the K of the models.
    claim_rule: what Fig. 3.9's complex-motion claim compares: equal_error (the K each primitive
        needs to reach each of ``equal_error_cm``: the thesis' "require more basis functions to
        achieve the same reconstruction error") or relative_drop (the cut-off rule's K, which
        mostly finds where a curve meets its noise floor).
    equal_error_cm: the joint-space RMSEs (cm) of ``claim_rule: equal_error``."""

    SECTION = "du2022_fda.basis"

    n_basis: tuple[int, ...] = (5, 6, 8, 10, 12, 15, 20, 25, 30)
    min_relative_drop: float = 0.05
    claim_rule: str = "equal_error"
    equal_error_cm: tuple[float, ...] = (0.25, 0.5, 1.0)


@dataclass(frozen=True)
class ReconstructionSettings(Settings):
    """Reconstruction errors against latent dimensions (Fig. 3.10) and latent spaces (Fig. 3.11).

    primitives: the primitives compared (Sec. 3.3.5: walk leftStance and two-hand picking reach).
    pick_primitive: the manipulation primitive of the pick claims (one of ``primitives``); Fig. 3.9
        compares its chosen basis size with those of the other ``primitives`` (Table 3.1: two-hand
        picking reach 25, walk leftStance 10).
    dims: numbers of latent dimensions evaluated (capped at clips - 1).
    normalized_variant: which normalized FPCA the Fig. 3.10 claims judge (all three are drawn):
        zscore_floored (the thesis' "0 mean and 1 standard deviation", each function's SD
        floored at ``normalized_sd_floor``), zscore (as written, weights up to 1e4 for functions
        that hardly move) or root_scaled (the author's pipeline: only the root translation
        scaled).
    normalized_sd_floor: the SD floor of zscore_floored: the SD of a unit-quaternion component
        whose rotation turns by 0.5 degrees (sin(0.25 deg)), the realism table's near-static
        channel (realism.near_static_deg)."""

    SECTION = "du2022_fda.reconstruction"

    primitives: tuple[str, ...] = ("walk_leftStance", "pick_reach")
    pick_primitive: str = "pick_reach"
    dims: tuple[int, ...] = (1, 2, 3, 5, 8, 12, 20, 30, 40)
    normalized_variant: str = "zscore_floored"
    normalized_sd_floor: float = 0.004363


@dataclass(frozen=True)
class SfpcaSettings(Settings):
    """SFPCA weight optimisation by L-BFGS-B (Sec. 3.3.4, Eq. 3.8;
    :class:`motionvar.du2022.fda.SFPCA`, whose constructor takes these defaults).

    weight_groups: ``function``: one weight per function (Sec. 3.3.4, "we scale each function
        with one weight"); ``joint``: one per joint quaternion (DFKI's implementation).
    gradient: ``autograd`` (torch) or ``finite_difference`` (scipy's own, the thesis' setting).
    max_iter: L-BFGS-B iterations per fit (the thesis gives no count; 50 fits the full run in
        a 2-core budget).
    tol: L-BFGS-B ftol (relative reduction of the objective that stops it).
    eval_frames_per_basis: the objective's forward kinematics runs at min(canonical frames,
        this x K) equally spaced frames (0: at every canonical frame, as Eq. 3.8).
    stop_window, stop_rtol: also stop once the objective fell by at most ``stop_rtol``
        (relative) over ``stop_window`` iterations (0: off; the thesis states no stopping rule;
        measured at full size with 50 iterations, walk_leftStance d = 5 fell 8 % after a
        10-iteration plateau, which a 5-iteration window at 0.1 % takes for convergence).
    eigensolver: how each evaluation of Eq. 3.8 finds its leading eigenvectors: ``tridiagonal``
        (Householder reduction, every eigenpair of the tridiagonal matrix, only the kept
        eigenvectors transformed back) or ``full`` (``torch.linalg.eigh``, every eigenvector);
        the same subspace and gradient to rounding, the first about twice as fast at 1,500
        coefficients."""

    SECTION = "du2022_fda.sfpca"

    weight_groups: str = "function"
    gradient: str = "autograd"
    max_iter: int = 50
    tol: float = 1e-6
    eval_frames_per_basis: int = 0
    stop_window: int = 0
    stop_rtol: float = 1e-3
    eigensolver: str = "tridiagonal"


@dataclass(frozen=True)
class GplvmSettings(Settings):
    """The Bayesian GPLVM baseline (Sec. 3.3.5, the thesis' GPy DPBayesianGPLVM;
    :class:`motionvar.models.bayesian_gplvm.BayesianGPLVM`).

    n_inducing: inducing inputs (capped at the number of clips).
    max_iter: L-BFGS-B iterations (the thesis gives no count; 200 fits the full run in a 2-core
        budget).
    noise_init: initial noise variance as a fraction of the data variance.
    discriminative_sigma2: sigma^2 of the discriminative prior on the latent means (Urtasun &
        Darrell 2007, GPy's DGPLVM prior), labels by k-means++ on joint positions (Sec. 3.3.5);
        None: plain Bayesian GPLVM.
    n_clusters: k-means++ clusters of the prior's labels (Sec. 3.3.5: 3 for walk leftStance)."""

    SECTION = "du2022_fda.gplvm"

    n_inducing: int = 30
    max_iter: int = 200
    noise_init: float = 0.01
    discriminative_sigma2: float | None = 1.0
    n_clusters: int = 3


@dataclass(frozen=True)
class LatentSettings(Settings):
    """Latent-space analysis (Fig. 3.11).

    n_components: latent dimension (Sec. 3.3.5: "reduced to 20 dimensions"; capped at clips - 1).
    tsne_perplexity: t-SNE perplexity (capped at (clips - 1) / 3).
    knn: k of the leave-one-out k-NN label accuracy."""

    SECTION = "du2022_fda.latent"

    n_components: int = 20
    tsne_perplexity: float = 30.0
    knn: int = 5


@dataclass(frozen=True)
class TableSettings(Settings):
    """Latent dimensions per primitive (Table 3.1).

    reference_components: SFPCA weights are optimised at this dimension (capped at
        clips - 1), then reused for every d (the thesis optimises them per dimension).
    max_components: largest dimension searched.
    observation_error_cm: the latent dimension is the smallest d whose mean joint
        reconstruction error is at most this (cm)."""

    SECTION = "du2022_fda.table"

    reference_components: int = 20
    max_components: int = 60
    observation_error_cm: float = 1.0


@dataclass(frozen=True)
class FdaSettings(Settings):
    """Config section ``du2022_fda`` (Du 2022 ch. 3).

    seed: seed of the GPLVM initialisation, k-means labels and t-SNE.
    behaviours: behaviours whose primitives are analysed (idle is a long recording, not a
        primitive).
    min_clips: primitives with fewer clips are left out.
    time_warping: canonical timeline of a primitive: ``dtw`` warps every clip to the
        median-length clip (Sec. 4.4.1), ``linear`` resamples every clip to the median length.
    basis, reconstruction, sfpca, gplvm, latent, table: the subsections above."""

    SECTION = "du2022_fda"

    seed: int = 0
    behaviours: tuple[str, ...] = ("walk", "run", "sidestep", "pick", "place")
    min_clips: int = 3
    time_warping: str = "dtw"
    basis: BasisSettings = field(default_factory=BasisSettings)
    reconstruction: ReconstructionSettings = field(default_factory=ReconstructionSettings)
    sfpca: SfpcaSettings = field(default_factory=SfpcaSettings)
    gplvm: GplvmSettings = field(default_factory=GplvmSettings)
    latent: LatentSettings = field(default_factory=LatentSettings)
    table: TableSettings = field(default_factory=TableSettings)
