"""Our hand-written methods against the reference libraries users know, side by side: the same
input through both, their agreement, our time, their time and the ratio, measured in one run.

    python benchmarks/reference_libraries.py [--quick]

Pairs (sizes of the default run, about 2.5 minutes on 2 cores; ``--quick`` is a smoke run of
about 20 s with smaller sizes):

1. FPCA (motionvar.du2022.fda.FPCA) vs scikit-fda FPCA: 400 clips x 127 functions (root + 31
   quaternions) x 10 cubic B-splines, 20 components; fit + scores. Agreement: largest
   difference of sign-aligned eigenfunction coefficients and of scores, relative to their
   largest magnitude; scikit-fda runs as shipped (its scikit-learn PCA is randomized at this
   size) and with the full SVD, and both are held against an exact SVD of the coefficients
   weighted by scikit-fda's own Gram matrix.
2. Bayesian GPLVM bound + gradient (motionvar.models.bayesian_gplvm) vs GPy BayesianGPLVM
   (RBF ARD): N = 500, Q = 20, M = 30 inducing inputs, D = 100 and 2000 outputs; one
   evaluation of the bound and its gradient at the same fixed parameters (GPy: one
   ``_objective_grads``; ours: the bound and torch backward). Agreement: relative difference
   of the bound, and the largest gradient difference relative to the gradient's largest entry
   (GPy's jitter term added, see tests/crosscheck/test_xc_gplvm_gpy.py).
3. Kriging, 2-D input (PyKrige's limit; Ma 2010's own inputs have more dimensions): 300
   examples, 50 output dimensions, 1000 query points, linear variogram. Ours: fit (trend,
   variogram, bordered inverse) + predict of all outputs at once. PyKrige (variogram given,
   not fitted): one model per output (its UniversalKriging constructor also computes
   leave-one-out statistics, most of its time). Two rows: ordinary Kriging of our residuals (the
   like-for-like check) and universal Kriging with a linear drift (a different estimator:
   the gap is reported in residual standard deviations, not as agreement).
4. BVH reading: a CMU file (131_01, 994 frames) with its frames repeated to ~100 MB in a
   temporary folder, read by ours, pybvh and bvhio (ours and pybvh: best of two reads, after
   each has read the source file once). Agreement: root positions and local
   rotation matrices against pybvh (float64) and bvhio (float32). A third row: the file's
   Euler angles to quaternions, ours (core.quaternions.euler_to_quat) against scipy's
   ``Rotation.from_euler``; agreement: the share of quaternions equal bit for bit.
5. DTW: 200 pairs of 100-frame 60-D sequences; ours (motionvar.prep.dtw_path, which calls
   dtaidistance's C ``warping_path_fast``) vs dtaidistance's ``dtw_ndim.warping_path`` (C
   matrix + Python backtracking). Agreement: identical paths, distance difference.

Ratio = their time / our time (> 1: ours is faster); each time is the best of 1-5 repeats.
Both sides run with the same thread limit (``--threads``, default 1; set for BLAS/OpenMP
through the environment before numpy loads, by threadpoolctl, and for torch): on a shared
2-core machine multi-threaded BLAS oversubscribes and times swing by 100x, so one thread
compares the algorithms. The header prints the load average; the numbers in
docs/reference_libraries.md were measured on 2 cores.
"""

from __future__ import annotations

import argparse
import datetime
import os
import platform
import sys
import tempfile
import time
import warnings
from functools import partial
from pathlib import Path
from unittest.mock import patch


def _threads_from_argv(argv: list[str]) -> str:
    """The ``--threads`` value, read before numpy loads its BLAS (a limit set later does not
    reach BLAS libraries that load later, such as scipy's when scikit-learn is imported)."""
    for i, arg in enumerate(argv):
        if arg.startswith("--threads="):
            return arg.split("=", 1)[1]
        if arg == "--threads" and i + 1 < len(argv):
            return argv[i + 1]
    return "1"


if __name__ == "__main__":
    for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
        os.environ[_var] = _threads_from_argv(sys.argv[1:])

import numpy as np  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
BVH_SOURCE = ROOT.parent / "shared" / "data" / "bvh" / "cmu" / "131_01.bvh"


def best_time(fn, repeat: int = 1):
    """(result of the last call, least wall time of ``repeat`` calls in seconds)."""
    best, out = np.inf, None
    for _ in range(repeat):
        start = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - start)
    return out, best


def rel(a, b) -> float:
    a, b = np.asarray(a, float), np.asarray(b, float)
    return float(np.abs(a - b).max() / max(np.abs(b).max(), 1e-300))


def missing(name: str, exc: Exception) -> dict:
    return {"agreement": f"{name} not installed ({type(exc).__name__})", "ours": np.nan, "theirs": np.nan}


# ---- 1. FPCA -------------------------------------------------------------------------------------


def bench_fpca(quick: bool) -> list[dict]:
    from motionvar.core import cmu_skeleton
    from motionvar.du2022.fda import FPCA, FunctionalMotions, FunctionLayout
    from motionvar.du2022.fda.bspline import BSplineBasis

    N, K, J, n = (60, 10, 31, 10) if quick else (400, 10, 31, 20)
    size = f"{N} clips x {3 + 4 * J} fn x {K} B-splines, {n} PCs"
    try:
        from skfda.preprocessing.dim_reduction import FPCA as SkFPCA
        from skfda.preprocessing.dim_reduction import _fpca as skfda_fpca_module
        from skfda.representation.basis import BSplineBasis as SkBSpline
        from skfda.representation.basis import FDataBasis, VectorValuedBasis
        from sklearn.decomposition import PCA
    except Exception as exc:  # noqa: BLE001 - any import failure means "not usable here"
        return [{"pair": "FPCA vs scikit-fda", "size": size, **missing("scikit-fda", exc)}]
    rng = np.random.default_rng(0)
    D = 3 + 4 * J
    coefs = np.cumsum(rng.normal(size=(N, K, D)), axis=1) * rng.uniform(0.1, 1.0, size=D)
    sk = cmu_skeleton()
    fd = FunctionalMotions(
        coefs=coefs,
        basis=BSplineBasis(K),
        layout=FunctionLayout(J),
        offsets=np.broadcast_to(sk.offsets, (N, J, 3)).copy(),
        parents=sk.parents,
        n_frames=60,
    )

    def ours():
        model = FPCA(n).fit(fd)
        return model, model.transform(fd)

    basis = VectorValuedBasis([SkBSpline(domain_range=(0, 1), n_basis=K, order=4)] * D)

    def theirs():
        X = FDataBasis(basis, coefs.transpose(0, 2, 1).reshape(N, D * K))
        model = SkFPCA(n_components=n).fit(X)
        return model, model.transform(X)

    def theirs_full():
        with patch.object(skfda_fpca_module, "PCA", partial(PCA, svd_solver="full")):
            return theirs()

    (mo, so), t_ours = best_time(ours, 3)
    (mt, st), t_theirs = best_time(theirs, 2)
    (mf, sf), t_full = best_time(theirs_full, 2)
    # exact explained variances: SVD of the centred coefficients times a Cholesky factor of scikit-fda's Gram
    X = FDataBasis(basis, coefs.transpose(0, 2, 1).reshape(N, D * K))
    c = X.coefficients - X.coefficients.mean(axis=0)
    exact = np.linalg.svd(c @ np.linalg.cholesky(basis.gram_matrix()), compute_uv=False)[:n] ** 2 / (N - 1)
    rows = []
    for label, (m, sc, t) in {"as shipped (randomized PCA)": (mt, st, t_theirs), "full SVD": (mf, sf, t_full)}.items():
        funcs = m.components_.coefficients.reshape(n, D, K).transpose(0, 2, 1)
        sign = np.sign(np.einsum("nkd,nkd->n", mo.eigenfunctions_, funcs))
        agree = (
            f"eigenfunctions {rel(mo.eigenfunctions_, sign[:, None, None] * funcs):.1e}, "
            f"scores {rel(so, sc * sign):.1e}; variances vs exact: ours {rel(mo.explained_variance_, exact):.1e}, "
            f"theirs {rel(m.explained_variance_, exact):.1e}"
        )
        rows.append(
            {"pair": f"FPCA vs scikit-fda, {label}", "size": size, "agreement": agree, "ours": t_ours, "theirs": t}
        )
    return rows


# ---- 2. Bayesian GPLVM ---------------------------------------------------------------------------


def bench_gplvm(quick: bool) -> list[dict]:
    import torch

    from motionvar.models.bayesian_gplvm import BayesianGPLVM

    N, Q, M = (100, 5, 15) if quick else (500, 20, 30)
    outputs = (50,) if quick else (100, 2000)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            import GPy
    except Exception as exc:  # noqa: BLE001
        return [{"pair": "Bayesian GPLVM bound+grad vs GPy", "size": f"N={N}, Q={Q}", **missing("GPy", exc)}]
    rows = []
    for D in outputs:
        rng = np.random.default_rng(D)
        Y = rng.normal(size=(N, 8)) @ rng.normal(size=(8, D)) + 0.3 * rng.normal(size=(N, D))
        Y = (Y - Y.mean(0)) / Y.std()
        mu, S = rng.normal(size=(N, Q)), rng.uniform(0.05, 0.5, size=(N, Q))
        Z, sf2, ell, noise = rng.normal(size=(M, Q)), 1.3, rng.uniform(1.0, 4.0, size=Q), 0.2
        jitter = 1e-8  # GPy's VarDTC const_jitter; ours scales its jitter by sf2
        model = BayesianGPLVM(n_components=Q, n_inducing=M, jitter=jitter / sf2)
        Yt, YY = torch.tensor(Y), float(np.sum(Y**2))
        raw = {"mu": mu, "log_S": np.log(S), "Z": Z, "log_sf2": np.log([sf2]), "log_ell": np.log(ell)}
        raw["log_noise"] = np.log([noise])

        def ours():
            p = {k: torch.tensor(v, dtype=torch.float64, requires_grad=True) for k, v in raw.items()}
            bound, _ = model._bound(p, Yt, YY, None)
            bound.backward()
            return float(bound.detach()), {k: v.grad.numpy() for k, v in p.items()}

        kern = GPy.kern.RBF(Q, variance=sf2, lengthscale=ell, ARD=True)
        m = GPy.models.BayesianGPLVM(
            Y, Q, X=mu.copy(), X_variance=S.copy(), Z=Z.copy(), kernel=kern, num_inducing=M,
            likelihood=GPy.likelihoods.Gaussian(variance=noise),
        )  # fmt: skip
        x0 = m.optimizer_array.copy()

        def theirs():
            return m._objective_grads(x0)

        (b_ours, g), t_ours = best_time(ours, 5)
        _, t_theirs = best_time(theirs, 5)
        b_gpy = float(np.ravel(m.log_likelihood())[0])
        ours_g = np.concatenate(
            [
                g["mu"].ravel(),
                (g["log_S"] / S).ravel(),
                g["Z"].ravel(),
                g["log_sf2"] / sf2 - jitter / sf2 * np.trace(m.grad_dict["dL_dKmm"]),
                g["log_ell"] / ell,
                g["log_noise"] / noise,
            ]
        )
        gpy_g = np.concatenate(
            [
                np.ravel(m.X.mean.gradient),
                np.ravel(m.X.variance.gradient),
                np.ravel(m.Z.gradient),
                np.ravel(m.kern.variance.gradient),
                np.ravel(m.kern.lengthscale.gradient),
                np.ravel(m.likelihood.variance.gradient),
            ]
        )
        agree = f"bound {abs(b_ours - b_gpy) / abs(b_gpy):.1e}, gradient {rel(ours_g, gpy_g):.1e}"
        rows.append(
            {
                "pair": "Bayesian GPLVM bound+grad vs GPy",
                "size": f"N={N}, Q={Q}, M={M}, D={D}",
                "agreement": agree,
                "ours": t_ours,
                "theirs": t_theirs,
            }
        )
    return rows


# ---- 3. Kriging ----------------------------------------------------------------------------------


def bench_kriging(quick: bool) -> list[dict]:
    from motionvar.ma2010.kriging import UniversalKriging

    N, D, Mq = (100, 10, 200) if quick else (300, 50, 1000)
    size = f"{N} examples (2-D) x {D} outputs, {Mq} queries"
    try:
        from pykrige.ok import OrdinaryKriging
        from pykrige.uk import UniversalKriging as PyKrigeUK
    except Exception as exc:  # noqa: BLE001
        pairs = ("Kriging of residuals vs PyKrige OK", "Universal Kriging (lin. drift) vs PyKrige UK")
        return [{"pair": pair, "size": size, **missing("PyKrige", exc)} for pair in pairs]
    rng = np.random.default_rng(3)
    x = rng.uniform(0, 4, size=(N, 2))
    freq = rng.uniform(0.5, 2.0, size=(2, D))
    y = 1.0 + x @ rng.normal(size=(2, D)) + np.sin(x @ freq + rng.uniform(0, 6, size=D))
    xq = rng.uniform(0, 4, size=(Mq, 2))

    def ours():
        model = UniversalKriging("linear", standardize=False, variogram_scale="none").fit(x, y)
        return model, model.predict(xq)

    (model, pred), t_ours = best_time(ours, 2)
    v = model.variogram_
    params = [v.params[0], v.nugget]
    lam, _ = model.weights(xq)
    res_ours = lam @ model.residuals_

    def theirs_ok():
        out = np.empty((Mq, D))
        for d in range(D):
            ok = OrdinaryKriging(x[:, 0], x[:, 1], model.residuals_[:, d], variogram_model="linear",
                                 variogram_parameters=params)  # fmt: skip
            out[:, d] = ok.execute("points", xq[:, 0], xq[:, 1])[0]
        return out

    def theirs_uk():
        out = np.empty((Mq, D))
        for d in range(D):
            uk = PyKrigeUK(x[:, 0], x[:, 1], y[:, d], variogram_model="linear", variogram_parameters=params,
                           drift_terms=["regional_linear"])  # fmt: skip
            out[:, d] = uk.execute("points", xq[:, 0], xq[:, 1])[0]
        return out

    ok_pred, t_ok = best_time(theirs_ok)
    uk_pred, t_uk = best_time(theirs_uk)
    gap = np.abs(pred - uk_pred).max(axis=0) / model.residuals_.std(axis=0)
    return [
        {
            "pair": "Kriging of residuals vs PyKrige OK",
            "size": size,
            "agreement": f"predictions {rel(res_ours, ok_pred):.1e}",
            "ours": t_ours,
            "theirs": t_ok,
        },
        {
            "pair": "Universal Kriging (lin. drift) vs PyKrige UK",
            "size": size,
            "agreement": f"different estimators: gap up to {gap.max():.2f} residual sd (median {np.median(gap):.2f})",
            "ours": t_ours,
            "theirs": t_uk,
        },
    ]


# ---- 4. BVH --------------------------------------------------------------------------------------


def big_bvh(source: Path, target_mb: float, folder: Path) -> tuple[Path, int]:
    """``source`` with its frames repeated until the file has about ``target_mb`` MB."""
    text = source.read_text()
    head, motion = text.split("MOTION", 1)
    lines = motion.strip("\n").split("\n")
    frames = [ln for ln in lines[2:] if ln.strip()]
    body = "\n".join(frames) + "\n"
    reps = max(1, int(round(target_mb * 1e6 / len(body.encode()))))
    path = folder / f"{source.stem}_x{reps}.bvh"
    with path.open("w") as f:
        f.write(head + "MOTION\n" + f"Frames: {len(frames) * reps}\n" + lines[1] + "\n")
        for _ in range(reps):
            f.write(body)
    return path, len(frames) * reps


def bench_bvh(quick: bool) -> list[dict]:
    from scipy.spatial.transform import Rotation

    from motionvar.io.bvh import read_bvh

    if not BVH_SOURCE.is_file():
        return [
            {"pair": f"BVH read vs {lib}", "size": "-", "agreement": f"{BVH_SOURCE} not found", "ours": np.nan}
            for lib in ("pybvh", "bvhio")
        ]
    target = 2.0 if quick else 100.0
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        path, n_frames = big_bvh(BVH_SOURCE, target, Path(tmp))
        size = f"{path.stat().st_size / 1e6:.0f} MB, {n_frames} frames x 31 joints"
        # each reader first reads the small source file (its imports and first calls are not
        # what is compared), then the big one, best of ``repeat``
        repeat = 1 if quick else 2
        read_bvh(BVH_SOURCE)
        ours, t_ours = best_time(lambda: read_bvh(path), repeat)
        R_ours = Rotation.from_quat(ours.rotations.reshape(-1, 4)[:, [1, 2, 3, 0]]).as_matrix()
        try:
            import pybvh

            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                pybvh.read_bvh_file(BVH_SOURCE, warn_on_world_up_disagreement=False)
                b, t_b = best_time(lambda: pybvh.read_bvh_file(path, warn_on_world_up_disagreement=False), repeat)
            agree = f"root {rel(ours.root_pos, b.root_pos):.1e}, rotations {rel(R_ours, b.to_rotmat()[1].reshape(-1, 3, 3)):.1e}"
            rows.append({"pair": "BVH read vs pybvh", "size": size, "agreement": agree, "ours": t_ours, "theirs": t_b})
            del b
        except ImportError as exc:
            rows.append({"pair": "BVH read vs pybvh", "size": size, **missing("pybvh", exc)})
        try:
            import bvhio

            c, t_c = best_time(lambda: bvhio.readAsBvh(str(path)))
            keys = c.Root.Keyframes  # the root: positions and rotations, float32
            root = np.array([list(k.Position) for k in keys])
            q = np.array([[k.Rotation.x, k.Rotation.y, k.Rotation.z, k.Rotation.w] for k in keys])
            R_root = Rotation.from_quat(q).as_matrix()
            agree = f"root {rel(ours.root_pos, root):.1e}, root rotations {rel(R_ours.reshape(n_frames, -1, 3, 3)[:, 0], R_root):.1e}"
            rows.append({"pair": "BVH read vs bvhio", "size": size, "agreement": agree, "ours": t_ours, "theirs": t_c})
            del c
        except ImportError as exc:
            rows.append({"pair": "BVH read vs bvhio", "size": size, **missing("bvhio", exc)})
        rows.append(bench_euler(path, n_frames))
    return rows


def bench_euler(path: Path, n_frames: int) -> dict:
    """The file's joint angles (ZYX channels, CMU) to quaternions: ours against scipy."""
    from scipy.spatial.transform import Rotation

    from motionvar.core.quaternions import euler_to_quat
    from motionvar.io.bvh import _frame_values

    text = path.read_text()
    body = text[text.index("\n", text.index("Frame Time")) + 1 :]
    angles = _frame_values(body)[:, 3:].reshape(-1, 3)
    ours, t_ours = best_time(lambda: euler_to_quat(angles, "ZYX"), repeat=3)
    ref, t_ref = best_time(lambda: Rotation.from_euler("ZYX", angles, degrees=True).as_quat(scalar_first=True), 3)
    same = float(np.mean(np.all((ours == ref) & (np.signbit(ours) == np.signbit(ref)), axis=1)))
    size = f"{len(angles):,} rotations ({n_frames} frames)"
    agree = f"{same:.0%} of quaternions bit-identical"
    return {"pair": "Euler to quaternion vs scipy", "size": size, "agreement": agree, "ours": t_ours, "theirs": t_ref}


# ---- 5. DTW --------------------------------------------------------------------------------------


def bench_dtw(quick: bool) -> list[dict]:
    from dtaidistance import dtw_ndim

    from motionvar.prep import dtw_path

    n_pairs, T, D = (20, 100, 60) if quick else (200, 100, 60)
    rng = np.random.default_rng(5)
    pairs = [
        (np.cumsum(rng.normal(size=(T, D)), 0), np.cumsum(rng.normal(size=(T + int(rng.integers(-10, 11)), D)), 0))
        for _ in range(n_pairs)
    ]
    ours, t_ours = best_time(lambda: [dtw_path(a, b) for a, b in pairs], 2)
    theirs, t_theirs = best_time(lambda: [np.array(dtw_ndim.warping_path(a, b, use_c=True)) for a, b in pairs], 2)
    same = sum(np.array_equal(p, q) for p, q in zip(ours, theirs))
    d_ours = np.array([np.sqrt(((a[p[:, 0]] - b[p[:, 1]]) ** 2).sum()) for (a, b), p in zip(pairs, ours)])
    d_theirs = np.array([dtw_ndim.distance(a, b, use_c=True) for a, b in pairs])
    return [
        {
            "pair": "DTW path vs dtaidistance",
            "size": f"{n_pairs} pairs, ~{T} frames x {D}-D",
            "agreement": f"{same}/{n_pairs} paths identical, distance {rel(d_ours, d_theirs):.1e}",
            "ours": t_ours,
            "theirs": t_theirs,
        }
    ]


# ---- table ---------------------------------------------------------------------------------------


def machine() -> str:
    cpu = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return f"{cpu}, {len(os.sched_getaffinity(0))} cores, Python {platform.python_version()}"


def versions() -> str:
    from importlib.metadata import PackageNotFoundError, version

    out = []
    for name in ("numpy", "scipy", "torch", "scikit-fda", "GPy", "PyKrige", "pybvh", "bvhio", "dtaidistance"):
        try:
            out.append(f"{name} {version(name)}")
        except PackageNotFoundError:
            out.append(f"{name} -")
    return ", ".join(out)


def fmt_s(t: float) -> str:
    return "-" if not np.isfinite(t) else (f"{t * 1e3:.1f} ms" if t < 1 else f"{t:.2f} s")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="small sizes (a smoke run of a few seconds)")
    parser.add_argument("--threads", type=int, default=1, help="BLAS/OpenMP/torch threads for both sides (default 1)")
    parser.add_argument("--only", nargs="*", choices=["fpca", "gplvm", "kriging", "bvh", "dtw"], help="pairs to run")
    args = parser.parse_args(argv)
    benches = {"fpca": bench_fpca, "gplvm": bench_gplvm, "kriging": bench_kriging, "bvh": bench_bvh, "dtw": bench_dtw}
    import torch
    from threadpoolctl import threadpool_limits

    threadpool_limits(args.threads)
    torch.set_num_threads(args.threads)
    start = time.perf_counter()
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    print(f"{datetime.date.today()} | {machine()} | {args.threads} thread(s) per library | load average {load}")
    print(versions(), flush=True)
    rows = []
    for name, fn in benches.items():
        if args.only and name not in args.only:
            continue
        for row in fn(args.quick):
            rows.append(row)
            print(f"  {row['pair']}: {fmt_s(row['ours'])} vs {fmt_s(row.get('theirs', np.nan))}", file=sys.stderr)
    print()
    print("| pair | size | agreement (max relative difference) | ours | theirs | ratio theirs/ours |")
    print("|---|---|---|---|---|---|")
    for r in rows:
        theirs = r.get("theirs", np.nan)
        ratio = theirs / r["ours"] if np.isfinite(theirs) and np.isfinite(r["ours"]) else np.nan
        ratio_s = "-" if not np.isfinite(ratio) else f"{ratio:.1f}x"
        print(f"| {r['pair']} | {r['size']} | {r['agreement']} | {fmt_s(r['ours'])} | {fmt_s(theirs)} | {ratio_s} |")
    print(f"\ntotal {time.perf_counter() - start:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
