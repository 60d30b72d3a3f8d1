# Helpers of du2022_fda.smk (Du 2022 ch. 3), kept apart from its rules (snakemake --lint flags
# a rule file that defines functions).

FDA = "results/{dataset}/models/du2022_fda"
# the curves of one primitive are computed in jobs that can run side by side (the methods of
# motionvar.du2022.fda.evaluations.curves.METHODS, and the other normalized FPCA variants of
# curves.NORMALIZED_METHODS, seconds where the others take minutes)
FDA_PARTS = {
    "pca": ["fpca", "normalized_fpca", "sfpca"],
    "gplvm": ["gplvm"],
    "scaled": ["normalized_fpca_floored", "root_scaled_fpca"],
}
# SFPCA models at Table 3.1's reference dimension, one per primitive (rule du2022_fda_sfpca)
FDA_SFPCA = f"{FDA}/sfpca"


def fda_curve_files():
    """The curves and latents of Fig. 3.10/3.11 per primitive and part ({dataset} left open)."""
    return expand(
        f"{FDA}/curves/{{primitive}}_{{part}}.npz",
        primitive=config["du2022_fda"]["reconstruction"]["primitives"],
        part=list(FDA_PARTS),
        allow_missing=True,
    )


def fda_sfpca_files(primitive):
    """The model files (.npz, .json) of one primitive's reference SFPCA ({dataset} left open)."""
    return [f"{FDA_SFPCA}/{primitive}.npz", f"{FDA_SFPCA}/{primitive}.json"]


def fda_sfpca_models(wildcards):
    """Input function of Table 3.1: the reference SFPCA model files of the Fig. 3.10 primitives
    (du2022_fda.reconstruction.primitives, whose curves fit SFPCA at that dimension too) that
    checkpoint du2022_fda_basis found in the data; Table 3.1 fits the other primitives itself
    (one process for all of them: a job per primitive would cost more start-up than it saves)."""
    import pandas as pd

    path = checkpoints.du2022_fda_basis.get(dataset=wildcards.dataset).output.n_basis
    present = set(pd.read_csv(path)["primitive"])
    return [
        f.format(dataset=wildcards.dataset)
        for p in config["du2022_fda"]["reconstruction"]["primitives"] if p in present
        for f in fda_sfpca_files(p)
    ]
