# Du 2022 ch. 3, functional data analysis of motion primitives: cubic B-spline functions
# (Fig. 3.9), FPCA, normalized FPCA, SFPCA and a Bayesian GPLVM (Fig. 3.10, 3.11), latent
# dimensions per primitive (Table 3.1). Options: config.du2022_fda (config/schema.yaml; defaults:
# motionvar.du2022.fda.settings.FdaSettings), passed whole to every rule. Inputs:
# the aligned primitives of results/{dataset}/prep/, warped to a canonical timeline here.
# Library: motionvar.du2022.fda (evaluations/, figures.py).

include: "du2022_fda_helpers.smk"


rule du2022_fda_canonical:
    input:
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
    output:
        clips=f"{FDA}/canonical/clips.npz",
        metadata=f"{FDA}/canonical/metadata.csv",
    params:
        settings=section_for("du2022_fda"),
    log:
        ev_log("du2022_fda_canonical"),
    benchmark:
        ev_benchmark("du2022_fda_canonical")
    priority: PRIORITY["du2022_fda_canonical"]
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/du2022_fda_canonical.py"


# a checkpoint: the primitives it lists (n_basis.csv) decide which SFPCA models Table 3.1 reads
checkpoint du2022_fda_basis:
    input:
        clips=f"{FDA}/canonical/clips.npz",
        metadata=f"{FDA}/canonical/metadata.csv",
    output:
        rmse=f"{FDA}/basis_rmse.csv",
        n_basis=f"{FDA}/n_basis.csv",
    params:
        settings=section_for("du2022_fda"),
    log:
        ev_log("du2022_fda_basis"),
    benchmark:
        ev_benchmark("du2022_fda_basis")
    priority: PRIORITY["du2022_fda_basis"]
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/du2022_fda_basis.py"


# SFPCA of one Fig. 3.10 primitive at Table 3.1's reference dimension, fitted once: read by
# the primitive's curves (which fit SFPCA at that dimension too) and by Table 3.1.
rule du2022_fda_sfpca:
    input:
        clips=f"{FDA}/canonical/clips.npz",
        metadata=f"{FDA}/canonical/metadata.csv",
        n_basis=f"{FDA}/n_basis.csv",
    output:
        model=f"{FDA_SFPCA}/{{primitive}}.npz",
        settings=f"{FDA_SFPCA}/{{primitive}}.json",
    params:
        settings=section_for("du2022_fda"),
    log:
        ev_log("du2022_fda_sfpca", "{primitive}"),
    benchmark:
        ev_benchmark("du2022_fda_sfpca", "{primitive}")
    priority: PRIORITY["du2022_fda_sfpca"]
    threads: 1
    resources:
        mem_mb=4000,
    conda:
        ENV
    script:
        "../scripts/du2022_fda_sfpca.py"


rule du2022_fda_curves:
    input:
        clips=f"{FDA}/canonical/clips.npz",
        metadata=f"{FDA}/canonical/metadata.csv",
        n_basis=f"{FDA}/n_basis.csv",
        sfpca=lambda wc: fda_sfpca_files(wc.primitive) if "sfpca" in FDA_PARTS[wc.part] else [],
    output:
        curves=f"{FDA}/curves/{{primitive}}_{{part}}.npz",
    wildcard_constraints:
        part="|".join(FDA_PARTS),
    params:
        settings=section_for("du2022_fda"),
        methods=lambda wc: FDA_PARTS[wc.part],
    log:
        ev_log("du2022_fda_curves", "{primitive}_{part}"),
    benchmark:
        ev_benchmark("du2022_fda_curves", "{primitive}_{part}")
    priority: PRIORITY["du2022_fda_curves"]
    threads: 1
    resources:
        mem_mb=4000,
    conda:
        ENV
    script:
        "../scripts/du2022_fda_curves.py"


# The input sets of the evaluations (motionvar.du2022.catalog; rules made by evaluations.smk):
# the basis fit errors (Fig. 3.9), the reconstruction curves (Fig. 3.10-3.11), the canonical
# primitives with their basis sizes and SFPCA models (Table 3.1).
add_input_set("du2022_fda_rmse", {"rmse": f"{FDA}/basis_rmse.csv"})
add_input_set("du2022_fda_curves", {"curves": fda_curve_files()})
add_input_set(
    "du2022_fda_sfpca",
    {
        "clips": f"{FDA}/canonical/clips.npz",
        "metadata": f"{FDA}/canonical/metadata.csv",
        "n_basis": f"{FDA}/n_basis.csv",
        "sfpca": fda_sfpca_models,
    },
)
