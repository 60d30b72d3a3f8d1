"""Functional data analysis of motion clips (Du 2022, ch. 3): cubic B-spline functions
(Eq. 3.1-3.2), FPCA (Eq. 3.3-3.5), normalised FPCA, scaled FPCA (SFPCA, Eq. 3.6-3.8) and
a Bayesian GPLVM baseline (Fig. 3.10-3.11).

Typical use (one motion primitive, e.g. the aligned walk_leftStance clips)::

    from motionvar.du2022.fda import FunctionalMotions, SFPCA

    fd = FunctionalMotions.from_motions(motions, n_basis=10)   # (N, K, D) coefficients
    model = SFPCA(n_components=20).fit(fd)                      # weights by L-BFGS-B
    z = model.transform(fd)                                     # (N, 20) latent scores
    coefs = model.inverse_transform(z)                          # (N, K, D) back
    clips = model.to_motions(z, fps=120, skeleton=skeleton)     # back to Motions
    model.save("walk_leftStance"); model = SFPCA.load("walk_leftStance")  # .npz + .json

API:

- :class:`BSplineBasis` (n_basis, degree=3): equally spaced clamped knots on [0, 1];
  ``design``, ``gram`` (int phi_k phi_l), ``gram_sqrt``, ``fit`` (least squares),
  ``evaluate``. :func:`choose_n_basis`: the cut-off rule for K (Sec. 3.3.3).
- :class:`FunctionalMotions`: N clips as coefficients (N, K, D) with D = 3 + 4J
  functions (root translation in cm, then one sign-continuous unit quaternion per joint,
  joint 0's being the root orientation); per-clip bone offsets for forward kinematics;
  ``from_motions``, ``values``, ``motion_arrays``, ``positions`` (FK), ``to_motions``,
  ``subset``, ``with_coefs``. :func:`bspline_fit_rmse`: joint-space RMSE of the fit.
- :class:`FPCA`, :class:`NormalizedFPCA`, :class:`RootScaledFPCA`, :class:`SFPCA`, :class:`WeightedFPCA` (given
  weights), sklearn-style: ``fit(fd)``, ``transform(fd or coefs) -> (N, n)``,
  ``inverse_transform(z) -> (N, K, D)``, ``reconstruct(fd, n_components=None)`` (the
  eigenfunctions are nested: one fit serves every smaller dimension),
  ``to_motions(z, fps, skeleton=None)``, ``save(path)`` (``.npz`` arrays + ``.json``
  settings, :mod:`motionvar.io.model_file`), ``FPCA.load(path)`` (returns the saved
  class). Fitted attributes end in ``_``: ``mean_``, ``function_weights_``,
  ``components_``, ``eigenfunctions_``, ``explained_variance_ratio_``, ...; SFPCA adds
  ``init_``, ``loss_``, ``n_iter_``, ``fit_time_s_``. SFPCA's options: ``gradient``
  ("autograd" or the thesis' "finite_difference"), ``weight_groups``, ``max_iter``,
  ``n_eval_frames`` (frames at which its objective runs forward kinematics).
- :class:`BayesianGPLVM` (arrays) and :class:`FunctionalGPLVM` (functional data): the
  nonlinear baseline (Titsias & Lawrence 2010, optional discriminative prior).
- :mod:`.primitives`: a dataset's primitives as functional data:
  :func:`canonical_primitives` (time warping to a canonical timeline),
  :func:`choose_basis_sizes` (K per primitive, Fig. 3.9 cut-off), :func:`n_basis_of`,
  :func:`primitive_motions`, :func:`functional_primitive`, :func:`sfpca_for`.
- :mod:`.settings`: :class:`~.settings.FdaSettings`, config section ``du2022_fda`` (subsections
  ``basis``, ``reconstruction``, ``sfpca``, ``gplvm``, ``latent``, ``table``), the one place
  its defaults are written; the evaluations take it whole, :func:`sfpca_for` takes its
  ``sfpca`` part.
- :mod:`.evaluations`: one module per figure or table (Fig. 3.9-3.11, Table 3.1) and the
  shared measures :func:`feature_error`, :func:`observation_error`, :func:`knn_accuracy`,
  :func:`latent_separation` (silhouette, leave-one-out k-NN accuracy);
  :mod:`.figures` draws them.
"""

from ...core.lazy import lazy_exports

# The names below are imported on first use (PEP 562), so that a rule that needs only the
# canonical primitives or the B-splines does not pay for scikit-learn, scipy.optimize or
# torch at start-up (issue #16: start-up is a large share of the short rules' time).
_EXPORTS = {
    "...models.bayesian_gplvm": ["BayesianGPLVM"],
    ".bspline": ["BSplineBasis", "choose_n_basis", "frame_times"],
    ".fpca": ["FPCA", "NormalizedFPCA", "RootScaledFPCA", "WeightedFPCA", "functional_std", "zscore_weights"],
    ".functional_gplvm": ["FunctionalGPLVM"],
    ".functions": ["FunctionalMotions", "FunctionLayout", "align_quaternion_signs", "bspline_fit_rmse"],
    ".primitives": [
        "canonical_primitives",
        "choose_basis_sizes",
        "functional_primitive",
        "n_basis_of",
        "primitive_motions",
        "sfpca_for",
    ],
    ".sfpca": ["SFPCA", "ObservationObjective", "TopEigenvectors", "scatter_is_cheaper"],
    ".evaluations.measures": ["feature_error", "knn_accuracy", "latent_separation", "observation_error"],
}
__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)

__all__ = [
    "BSplineBasis",
    "BayesianGPLVM",
    "FPCA",
    "FunctionLayout",
    "FunctionalGPLVM",
    "FunctionalMotions",
    "NormalizedFPCA",
    "RootScaledFPCA",
    "ObservationObjective",
    "SFPCA",
    "TopEigenvectors",
    "WeightedFPCA",
    "align_quaternion_signs",
    "bspline_fit_rmse",
    "canonical_primitives",
    "choose_basis_sizes",
    "choose_n_basis",
    "feature_error",
    "frame_times",
    "functional_primitive",
    "functional_std",
    "knn_accuracy",
    "latent_separation",
    "n_basis_of",
    "observation_error",
    "primitive_motions",
    "scatter_is_cheaper",
    "sfpca_for",
    "zscore_weights",
]
