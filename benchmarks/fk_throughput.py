"""Forward-kinematics throughput, numpy vs torch (motionvar.core.fk / fk_torch).

Batch: 1,000 clips x 120 frames of the CMU 31-joint skeleton, random unit quaternions,
every clip with its own bone lengths, all computed in one vectorised call (the loop is
over joints only). Prints frames per second for numpy (float64) and torch (float64 and
float32, CPU, no autograd), the ratio torch / numpy, and the largest difference between
the two results.

    python benchmarks/fk_throughput.py [--clips 1000] [--frames 120] [--repeats 3] [--torch-threads N]

numpy runs on one core; torch uses its default thread count unless --torch-threads is
given (1 compares like with like). On a shared machine the best of --repeats runs is
still noisy: compare ratios from the same run.
"""

from __future__ import annotations

import argparse
import time

import numpy as np
import torch

from motionvar.core import cmu_skeleton, fk, fk_torch
from motionvar.core.quaternions import qnormalize


def best_time(fn, repeats: int) -> float:
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return min(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--clips", type=int, default=1000)
    parser.add_argument("--frames", type=int, default=120)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--torch-threads", type=int, default=None)
    args = parser.parse_args()
    if args.torch_threads:
        torch.set_num_threads(args.torch_threads)

    sk = cmu_skeleton()
    rng = np.random.default_rng(0)
    shape = (args.clips, args.frames, sk.n_joints)
    rotations = qnormalize(rng.normal(size=(*shape, 4)))
    root = rng.normal(scale=50.0, size=(args.clips, args.frames, 3))
    offsets = sk.offsets * rng.uniform(0.9, 1.1, size=(args.clips, 1, sk.n_joints, 1))  # per-clip bones
    n_frames = args.clips * args.frames

    ref = fk(rotations, root, offsets, sk.parents)
    t_np = best_time(lambda: fk(rotations, root, offsets, sk.parents), args.repeats)
    print(
        f"FK, {args.clips} clips x {args.frames} frames x {sk.n_joints} joints, "
        f"torch {torch.__version__} with {torch.get_num_threads()} threads"
    )
    print(f"numpy   float64: {n_frames / t_np:12,.0f} frames/s ({t_np:.3f} s)")

    for dtype in (torch.float64, torch.float32):
        r, p, o = (torch.as_tensor(a, dtype=dtype) for a in (rotations, root, offsets))
        with torch.no_grad():
            out = fk_torch(r, p, o, sk.parents).numpy()
            t = best_time(lambda: fk_torch(r, p, o, sk.parents), args.repeats)
        name = str(dtype).replace("torch.", "")
        diff = np.abs(out - ref).max()
        print(
            f"torch   {name}: {n_frames / t:12,.0f} frames/s ({t:.3f} s), "
            f"torch/numpy = {t_np / t:.2f}x, max |difference| {diff:.1e} cm"
        )


if __name__ == "__main__":
    with torch.no_grad():
        main()
