# Stage 2: foot contacts, segmentation into primitives and alignment
# (results/{dataset}/prep/; settings: config.prep, motionvar.prep.PrepOptions).


rule preprocess:
    input:
        clips=f"{DATA}/clips.npz",
        metadata=f"{DATA}/metadata.csv",
        joint_map=joint_map_input,
    output:
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
        dropped=f"{PREP}/dropped.csv",
    params:
        settings=config["prep"],
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("preprocess"),
    benchmark:
        ev_benchmark("preprocess")
    threads: 1
    resources:
        mem_mb=4000,
    conda:
        ENV
    script:
        "../scripts/preprocess.py"
