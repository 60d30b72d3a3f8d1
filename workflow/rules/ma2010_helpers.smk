# Helpers of ma2010.smk (Ma et al. 2010), kept apart from its rules: paths, and the files of the
# evaluations' input sets (workflow/rules/evaluations.smk makes their rules from the declarations
# of motionvar.ma2010.catalog).

MA2010 = "results/{dataset}/models/ma2010"

# inputs of an evaluation: the packed dataset, or the walking cycles of rule ma2010_clips
MA2010_INPUTS = {
    "data": {"clips": f"{DATA}/clips.npz", "metadata": f"{DATA}/metadata.csv"},
    "walks": {
        "clips": f"{MA2010}/walk_clips.npz",
        "clips_settings": f"{MA2010}/walk_clips.json",
        "table": f"{MA2010}/walk_cycles.csv",
    },
}
# the fitted model, written by rule ma2010_model (motionvar.ma2010.storage), read by `motionvar ma2010`;
# built with ma2010_fig6 (same needs: walking cycles)
MA2010_MODEL = [f"{MA2010}/style_variation.npz", f"{MA2010}/style_variation.json"]


# the input sets of the evaluations (motionvar.ma2010.catalog): the packed dataset, or the walking
# cycles (with the model of Sec. 5-6 fitted to them when the rule runs: ma2010_walks_model)
add_input_set("ma2010_data", {**MA2010_INPUTS["data"], "joint_map": joint_map_input})
add_input_set("ma2010_walks", {**MA2010_INPUTS["walks"], "joint_map": joint_map_input})
add_input_set("ma2010_walks_model", {**MA2010_INPUTS["walks"], "joint_map": joint_map_input})

add_to_evaluation("ma2010_fig6", extra=tuple(MA2010_MODEL))
# its rivals run on two torch/BLAS threads inside (sec7_4.RIVAL_THREADS: the same numbers whatever
# cores the job gets; 95-125 % of one core, measured); the GIF takes its frame rate and panel size
# from config section report, the only keys of it passed (an edit of another report key does not
# rerun Sec. 7.4)
add_to_evaluation(
    "ma2010_sec7_4",
    outputs={
        "animation": in_report(
            "results/{dataset}/figures/ma2010_sec7_4.gif", "ma2010", "../report/ma2010_sec7_4.rst",
            page="gif_page_ma2010_sec7_4",
            figure="Sec. 7.4", kind="animation",
        ),
    },
    params={"report": {k: config["report"][k] for k in ("animation_fps", "animation_panel_px")}},
)
