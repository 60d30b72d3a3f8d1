"""Fixed thread counts for a computation whose last bits depend on them (a chaotic fit
amplifies how BLAS or torch split a product over threads), so that its numbers do not
change with the cores a job is given."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager


@contextmanager
def fixed_threads(n: int) -> Iterator[None]:
    """Run the block with ``n`` BLAS/OpenMP threads (threadpoolctl) and ``n`` torch
    intra-op threads, whatever the environment (e.g. Snakemake's ``OMP_NUM_THREADS`` for a
    one-core job) set; both are restored afterwards. Imports torch."""
    import torch
    from threadpoolctl import threadpool_limits

    before = torch.get_num_threads()
    with threadpool_limits(int(n)):
        torch.set_num_threads(int(n))
        try:
            yield
        finally:
            torch.set_num_threads(before)
