"""Benchmark of Du 2022 ch. 3 functional PCA (motionvar.du2022.fda), printed as ratios against
baselines measured in the same run:

1. SFPCA fit (Eq. 3.8) with torch-autograd gradients vs scipy's finite differences (the
   thesis' L-BFGS-B setting): seconds per L-BFGS-B iteration and their ratio, on the
   same clips and start point.
2. The full SFPCA fit at the target size (default 1,000 clips x 10 basis functions x
   31 joints, 20 components) against the target of 60 s on 2 cores.
3. Our FPCA (Gram-weighted coefficients) vs the reference FPCA of the tests (PCA of
   densely sampled curves with quadrature weights) and scikit-fda's FPCA when it is
   installed: fit time ratio and the largest difference of explained-variance ratios.
4. One evaluation of Eq. 3.8 (value and gradient) from the clips' Gram matrix or the
   coefficients' scatter matrix, with either eigensolver (``TopEigenvectors``): seconds,
   ratio against the Gram matrix with ``torch.linalg.eigh``, and the relative differences.

The clips are smooth random motions on the CMU 31-joint rig (self-contained, no dataset
needed): what is measured is cost, which depends only on the sizes.

    python benchmarks/fda_sfpca.py [--clips 1000] [--fd-clips 200] [--fd-iter 2]
"""

from __future__ import annotations

import argparse
import time

import numpy as np
import torch

from motionvar.core import Motion, cmu_skeleton
from motionvar.core.quaternions import quat_about_axis
from motionvar.du2022.fda import (
    FPCA,
    SFPCA,
    FunctionalMotions,
    ObservationObjective,
    TopEigenvectors,
    scatter_is_cheaper,
)


def random_clips(n: int, seed: int = 0, frames=(50, 70)) -> list[Motion]:
    """Smooth clips on the CMU rig: each joint turns about a fixed axis by a few sinusoids."""
    rng = np.random.default_rng(seed)
    sk = cmu_skeleton()
    J = sk.n_joints
    axes = rng.normal(size=(J, 3))
    mix = rng.normal(size=(4, J)) * rng.uniform(0.05, 0.5, size=J)
    clips = []
    for _ in range(n):
        T = int(rng.integers(*frames))
        t = np.linspace(0, 1, T)[:, None]
        phase = rng.uniform(0, 2 * np.pi, size=4)
        angles = np.sin(2 * np.pi * t * np.array([1, 1, 2, 3]) + phase) @ (mix * rng.uniform(0.7, 1.3, size=(4, 1)))
        q = np.stack([quat_about_axis(axes[j], angles[:, j]) for j in range(J)], axis=1)
        root = np.concatenate([t * rng.uniform(60, 90), 90 + 2 * np.sin(4 * np.pi * t), t * 15 * rng.normal()], 1)
        clips.append(Motion(skeleton=sk.scaled(rng.uniform(0.9, 1.1)), root_pos=root, rotations=q, fps=120.0))
    return clips


def timed(fn):
    start = time.perf_counter()
    out = fn()
    return out, time.perf_counter() - start


def dense_reference_fpca(fd: FunctionalMotions, n: int, per_span: int = 20) -> np.ndarray:
    """Explained-variance ratios of a PCA of densely sampled curves (Simpson weights)."""
    breaks = np.unique(fd.basis.knots)
    t = np.unique(np.concatenate([np.linspace(a, b, per_span + 1) for a, b in zip(breaks[:-1], breaks[1:])]))
    w = np.ones_like(t)
    w[1:-1:2], w[2:-1:2] = 4, 2
    w *= (breaks[1] - breaks[0]) / per_span / 3
    x = (np.einsum("tk,nkd->ntd", fd.basis.design(t), fd.coefs) * np.sqrt(w)[None, :, None]).reshape(fd.n_clips, -1)
    x -= x.mean(0)
    s = np.linalg.svd(x, compute_uv=False) ** 2
    return s[:n] / s.sum()


def skfda_fpca(fd: FunctionalMotions, n: int):
    """scikit-fda's vector-valued FPCA on the same B-spline coefficients, or None."""
    try:
        import skfda
        from skfda.preprocessing.dim_reduction import FPCA as SkFPCA
        from skfda.representation.basis import BSplineBasis as SkB
        from skfda.representation.basis import FDataBasis, VectorValuedBasis
    except Exception:  # not installed (it is not a dependency) or incompatible
        return None
    K, D = fd.coefs.shape[1:]
    basis = VectorValuedBasis([SkB(domain_range=(0, 1), n_basis=K, order=fd.basis.degree + 1)] * D)
    data = FDataBasis(basis, fd.coefs.transpose(0, 2, 1).reshape(fd.n_clips, -1))
    return SkFPCA(n_components=n).fit(data).explained_variance_ratio_, skfda.__version__


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--clips", type=int, default=1000)
    ap.add_argument("--basis", type=int, default=10)
    ap.add_argument("--components", type=int, default=20)
    ap.add_argument("--max-iter", type=int, default=100)
    ap.add_argument("--fd-clips", type=int, default=200, help="clips for the autograd vs finite-difference comparison")
    ap.add_argument("--fd-iter", type=int, default=2, help="L-BFGS-B iterations for that comparison")
    ap.add_argument("--threads", type=int, default=2)
    args = ap.parse_args()
    torch.set_num_threads(args.threads)
    print(f"torch {torch.__version__}, {torch.get_num_threads()} threads")

    clips = random_clips(args.clips)
    fd, t_fit = timed(lambda: FunctionalMotions.from_motions(clips, args.basis))
    print(
        f"data: {fd.n_clips} clips x {args.basis} basis functions x {fd.layout.n_joints} joints "
        f"({fd.layout.n_functions} functions, {fd.n_frames} canonical frames); B-spline fit {t_fit:.2f} s"
    )

    # 1. autograd vs finite differences, same start, same number of iterations
    small = fd.subset(np.arange(min(args.fd_clips, fd.n_clips)))
    SFPCA(args.components, max_iter=1).fit(small)  # warm-up (torch initialisation)
    ag, t_ag = timed(lambda: SFPCA(args.components, max_iter=args.fd_iter).fit(small))
    fdm, t_fd = timed(lambda: SFPCA(args.components, gradient="finite_difference", max_iter=args.fd_iter).fit(small))
    per_ag, per_fd = t_ag / max(ag.n_iter_, 1), t_fd / max(fdm.n_iter_, 1)
    print(f"\n[1] SFPCA gradient, {small.n_clips} clips, {args.fd_iter} L-BFGS-B iterations")
    print(
        f"  autograd (float32 FK)          : {t_ag:7.2f} s, {ag.n_iter_} it, {ag.n_evals_} evals, "
        f"{per_ag:.2f} s/it, loss {ag.loss_raw_ if ag.init_ == 'raw' else ag.loss_normalized_:.3f} -> {ag.loss_:.3f} cm^2"
    )
    print(
        f"  finite differences (float64 FK): {t_fd:7.2f} s, {fdm.n_iter_} it, {fdm.n_evals_} evals, "
        f"{per_fd:.2f} s/it, loss -> {fdm.loss_:.3f} cm^2"
    )
    print(f"  ratio finite differences / autograd per iteration: {per_fd / per_ag:.1f}x")

    # 2. full fit at the target size: the pipeline's settings (FK at 2 frames per basis
    # function, 50 iterations, config/config.yaml) and the thesis-like ones (every frame)
    print(f"\n[2] SFPCA fit, {fd.n_clips} clips, {args.components} components")
    settings = [
        ("pipeline: FK at 2 frames/basis, max_iter 50", dict(max_iter=50, n_eval_frames=2 * args.basis)),
        (f"every canonical frame, max_iter {args.max_iter}", dict(max_iter=args.max_iter)),
    ]
    for label, kwargs in settings:
        model, t_full = timed(lambda: SFPCA(args.components, **kwargs).fit(fd))
        print(
            f"  {label}: {t_full:.1f} s ({model.n_iter_} it, {model.n_evals_} evals); target 60 s -> "
            f"{'met' if t_full < 60 else 'MISSED'} (ratio {t_full / 60:.2f}); init {model.init_}, "
            f"loss raw {model.loss_raw_:.3f} / normalized {model.loss_normalized_:.3f} -> {model.loss_:.3f} cm^2"
        )

    # 3. FPCA vs references
    ours, t_ours = timed(lambda: FPCA(args.components).fit(fd).explained_variance_ratio_)
    ref, t_ref = timed(lambda: dense_reference_fpca(fd, args.components))
    print(f"\n[3] FPCA, {args.components} components")
    print(f"  ours (Gram-weighted coefficients): {t_ours:.3f} s")
    print(
        f"  dense quadrature reference      : {t_ref:.3f} s  ratio {t_ref / t_ours:.1f}x, "
        f"max |EVR difference| {np.max(np.abs(ours - ref)):.1e}"
    )
    sk = skfda_fpca(fd, args.components)
    if sk is None:
        print("  scikit-fda: not installed (not a dependency); skipped")
    else:
        out, t_sk = timed(lambda: skfda_fpca(fd, args.components))
        print(
            f"  scikit-fda {out[1]}             : {t_sk:.3f} s  ratio {t_sk / t_ours:.1f}x, "
            f"max |EVR difference| {np.max(np.abs(ours - out[0])):.1e}"
        )

    # 4. one evaluation of Eq. 3.8 (value and gradient) from the Gram or the scatter matrix,
    # with either eigensolver, against the Gram matrix with torch.linalg.eigh
    print(f"\n[4] SFPCA objective, one value + gradient, {args.components} components")
    w = np.random.default_rng(1).uniform(0.5, 2.0, fd.layout.n_functions)
    base = None
    for route in ("gram", "scatter"):
        for solver in sorted(TopEigenvectors.SOLVERS):  # "full" (the baseline) first
            obj = ObservationObjective(fd, args.components, n_eval_frames=2 * args.basis, eigensolver=solver)
            obj.scatter = obj.centred.T @ obj.centred if route == "scatter" else None
            obj.value_and_grad(w)  # warm-up
            (value, grad), t_eval = timed(lambda: obj.value_and_grad(w))
            base = base or (t_eval, value, grad)
            diff = np.abs(grad - base[2]).max() / np.abs(base[2]).max()
            print(
                f"  {route:7s} {solver:11s}: {t_eval:.3f} s  ratio {t_eval / base[0]:.2f}, "
                f"value {abs(value - base[1]) / base[1]:.1e} gradient {diff:.1e} (relative)"
            )
    print(
        f"  the objective's own choice: {'scatter' if scatter_is_cheaper(fd.n_clips, obj.centred.shape[1]) else 'gram'}"
    )


if __name__ == "__main__":
    main()
