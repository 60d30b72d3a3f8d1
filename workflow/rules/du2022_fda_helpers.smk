# Helpers of du2022_fda.smk (Du 2022 ch. 3), kept apart from its rules (snakemake --lint flags
# a rule file that defines functions).

FDA = "results/{dataset}/models/du2022_fda"
FDA_METHODS = ["fpca", "normalized_fpca", "sfpca", "gplvm"]
# the curves of one primitive are computed in two jobs that can run side by side
FDA_PARTS = {"pca": ["fpca", "normalized_fpca", "sfpca"], "gplvm": ["gplvm"]}


def fda_curve_files():
    """The curves and latents of Fig. 3.10/3.11 per primitive and part ({dataset} left open)."""
    return expand(
        f"{FDA}/curves/{{primitive}}_{{part}}.npz",
        primitive=config["fda"]["reconstruction"]["primitives"],
        part=list(FDA_PARTS),
        allow_missing=True,
    )
