"""Rule du2022_fda_curves (Du 2022 Fig. 3.10-3.11): for one primitive and each method
(FPCA, normalized FPCA, SFPCA, Bayesian GPLVM), the average reconstruction error in
feature and observation space for each number of latent dimensions, and the clips'
latent coordinates at the Fig. 3.11 dimension; one .npz per primitive, keys prefixed
by the method ("sfpca/observation_error", ...)."""


def _kmeans_labels(fd, positions, n_clusters: int, seed: int):
    """Thesis Sec. 3.3.5: labels of the discriminative prior from k-means++ on the clips'
    joint-position trajectories."""
    from sklearn.cluster import KMeans

    x = positions.reshape(fd.n_clips, -1)
    return KMeans(n_clusters=n_clusters, init="k-means++", n_init=10, random_state=seed).fit_predict(x)


def curves(method, fd, reference, dims, latent_dim, o):
    """([(feature error, observation error, fit seconds, note) per d], latent) of one method."""
    import logging
    import time

    from _du2022_fda import sfpca
    from motionvar.du2022.fda import FPCA, FunctionalGPLVM, NormalizedFPCA, feature_error, observation_error

    def errors(coefs):
        return feature_error(fd, coefs), observation_error(fd, coefs, reference=reference)

    rows = []
    if method in ("fpca", "normalized_fpca"):
        start = time.perf_counter()
        cls = FPCA if method == "fpca" else NormalizedFPCA
        model = cls(max(max(dims), latent_dim)).fit(fd)  # nested eigenfunctions: one fit serves every d
        fit_s = time.perf_counter() - start
        for d in dims:
            rows.append((*errors(model.reconstruct(fd, d)), fit_s, ""))
        return rows, model.transform(fd)[:, :latent_dim]

    gp = o["gplvm"]
    labels_dp = None
    if method == "gplvm" and gp["discriminative_sigma2"] is not None:
        labels_dp = _kmeans_labels(fd, reference, min(gp["n_clusters"], fd.n_clips - 1), o["seed"])
    latent = None
    for d in sorted(set(dims) | {latent_dim}):
        start = time.perf_counter()
        if method == "sfpca":
            model = sfpca(o, fd, d).fit(fd)
            note = f"init {model.init_}, {model.n_iter_} it, loss {model.loss_:.4g} cm^2"
        else:
            model = FunctionalGPLVM(d, n_inducing=gp["n_inducing"], max_iter=gp["max_iter"],
                                    noise_init=gp["noise_init"], discriminative_sigma2=gp["discriminative_sigma2"],
                                    random_state=o["seed"]).fit(fd, labels_dp)
            note = f"{model.gplvm_.n_iter_} it, {model.gplvm_.message_[:40]}"
        fit_s = time.perf_counter() - start
        logging.info("%s d=%d: %.1f s, %s", method, d, fit_s, note)
        if d == latent_dim:
            latent = model.transform(fd)
        if d in dims:
            rows.append((*errors(model.reconstruct(fd)), fit_s, note))
    return rows, latent


def main(snakemake) -> None:
    import numpy as np

    from _du2022_fda import functional, setup_threads

    setup_threads(snakemake)
    o = snakemake.params.options
    primitive = snakemake.wildcards.primitive
    fd, meta = functional(snakemake, primitive)
    n_max = fd.n_clips - 1  # rank of the centred data
    dims = sorted({d for d in o["reconstruction"]["dims"] if d <= n_max})
    if not dims:
        raise ValueError(f"config fda.reconstruction.dims: none <= {n_max} (clips - 1 of {primitive})")
    latent_dim = min(o["latent"]["n_components"], n_max)
    reference = fd.positions()
    out = {
        "primitive": np.array(primitive), "dims": np.array(dims), "latent_dim": np.array(latent_dim),
        "labels": np.array(meta["variant"].astype(str).tolist(), dtype=str),
        "n_basis": np.array(fd.basis.n_basis), "n_clips": np.array(fd.n_clips),
        "canonical_frames": np.array(fd.n_frames), "methods": np.array(snakemake.params.methods, dtype=str),
    }
    for method in snakemake.params.methods:
        rows, latent = curves(method, fd, reference, dims, latent_dim, o)
        feat, obs, seconds, notes = zip(*rows)
        out.update({f"{method}/feature_error": np.array(feat), f"{method}/observation_error": np.array(obs),
                    f"{method}/fit_seconds": np.array(seconds), f"{method}/info": np.array(notes, dtype=str),
                    f"{method}/latent": latent})
    with open(snakemake.output.curves, "wb") as fh:
        np.savez(fh, **out)


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
