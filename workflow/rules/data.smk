# Stage 1: the clips of a dataset, packed (results/{dataset}/data/clips.npz +
# metadata.csv): the synthetic generator or a labelled BVH folder (config.datasets),
# re-rooted at the pelvis where the BVH ROOT is not, and passed through the sanity gates
# (motionvar.io.plausibility) before anything is written.


rule data:
    input:
        data_input,
    output:
        clips=f"{DATA}/clips.npz",
        metadata=f"{DATA}/metadata.csv",
    params:
        entry=lambda wc: dataset_config(wc.dataset),
    log:
        ev_log("data"),
    benchmark:
        ev_benchmark("data")
    threads: lambda wc: 2 if dataset_config(wc.dataset)["source"] == "synthetic" else 1
    resources:
        mem_mb=4000,
    conda:
        ENV
    script:
        "../scripts/data.py"
