# Helpers of ma2010.smk (Ma et al. 2010), kept apart from its rules: paths and the registered
# evaluations (one EvaluationSpec each; workflow/rules/evaluations.smk makes their rules).

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


def _ma2010_spec(name, inputs, mem_mb=3000, **more):
    """An evaluation of Ma 2010 on ``inputs`` (a key of MA2010_INPUTS), with the dataset's
    joint map (input and param); every one runs on one core."""
    params = {"joint_map": lambda wc: joint_map_path(wc.dataset), **more.pop("params", {})}
    return EvaluationSpec(
        name, {**MA2010_INPUTS[inputs], "joint_map": joint_map_input}, mem_mb=mem_mb, params=params, **more
    )


MA2010_EVALUATIONS = [
    _ma2010_spec("ma2010_fig3", "data"),
    _ma2010_spec("ma2010_fig6", "walks", mem_mb=4000, extra=tuple(MA2010_MODEL)),
    _ma2010_spec("ma2010_variogram", "walks"),
    _ma2010_spec("ma2010_fig7b", "walks"),
    _ma2010_spec("ma2010_fig8", "walks"),
    # one core (95-125 % of one, measured): its rivals run on two torch/BLAS threads inside
    # (sec7_4.RIVAL_THREADS: the same numbers whatever cores the job gets); the GIF takes its
    # frame rate and panel size from config section report, the only keys of it passed (an
    # edit of another report key does not rerun Sec. 7.4)
    _ma2010_spec("ma2010_sec7_4", "walks", mem_mb=4000,
        outputs={
            "animation": in_report(
                "results/{dataset}/figures/ma2010_sec7_4.gif", "ma2010", "../report/ma2010_sec7_4.rst",
                figure="Sec. 7.4", kind="animation",
            ),
        },
        params={"report": {k: config["report"][k] for k in ("animation_fps", "animation_panel_px")}},
    ),
    _ma2010_spec("ma2010_sec8", "walks"),
]

for _spec in MA2010_EVALUATIONS:
    register_evaluation(_spec)
