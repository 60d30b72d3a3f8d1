# Ma et al. 2010, "Modeling Style and Variation in Human Motion": walking cycles cut at
# the key frames (Sec. 4), the hierarchical model (Sec. 5-6) and its evaluations
# (Fig. 3, 6, 7b, 8, Sec. 7.4, Sec. 8; one rule each, made by evaluations.smk from the
# declarations of motionvar.ma2010.catalog; their input sets in ma2010_helpers.smk).
# Options: config.ma2010 (motionvar.ma2010.settings.Ma2010Settings; config/schema.yaml); every
# rule passes the section as params.settings (section_for: less the keys one evaluation owns;
# the two stages before the evaluations only the subsection each reads: clips, model).

include: "ma2010_helpers.smk"


rule ma2010_clips:
    input:
        **MA2010_INPUTS["data"],
        joint_map=joint_map_input,
    output:
        clips=f"{MA2010}/walk_clips.npz",
        clips_settings=f"{MA2010}/walk_clips.json",
        table=f"{MA2010}/walk_cycles.csv",
    params:
        settings=section_for("ma2010", only=("clips",)),
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("ma2010_clips"),
    benchmark:
        ev_benchmark("ma2010_clips")
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/ma2010_clips.py"


# the model of Sec. 5-6 fitted once on all the walking cycles, saved for `motionvar ma2010`
# (it joins the default target with ma2010_fig6: MA2010_MODEL in ma2010_helpers.smk)
rule ma2010_model:
    input:
        **MA2010_INPUTS["walks"],
        joint_map=joint_map_input,
    output:
        model=MA2010_MODEL[0],
        settings=MA2010_MODEL[1],
    params:
        settings=section_for("ma2010", only=("model",)),
        joint_map=lambda wc: joint_map_path(wc.dataset),
    log:
        ev_log("ma2010_model"),
    benchmark:
        ev_benchmark("ma2010_model")
    threads: 1
    resources:
        mem_mb=3000,
    conda:
        ENV
    script:
        "../scripts/ma2010_model.py"

