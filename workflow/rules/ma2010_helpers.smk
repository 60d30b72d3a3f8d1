# Helpers of ma2010.smk (Ma et al. 2010), kept apart from its rules: paths, the registered
# evaluations and what each evaluation rule takes (ma2010.smk generates the rules).

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
# the model's keys; root_group places the root rotation when the joint groups are built
# (motionvar.ma2010.examples.WalkCycles), so every evaluation of the walking cycles reads it
_MODEL = ["structure", "variogram_model", "root_group"]
# the fitted model, written by rule ma2010_model (motionvar.ma2010.storage), read by `motionvar ma2010`;
# built with ma2010_fig6 (same needs: walking cycles)
MA2010_MODEL = [f"{MA2010}/style_variation.npz", f"{MA2010}/style_variation.json"]

# evaluation -> inputs, figure label, config.ma2010 keys its script reads, memory, and
# further outputs / params (every evaluation runs on one core)
MA2010_EVALUATIONS = {
    "ma2010_fig3": {
        "input": "data", "figure": "Fig. 3", "mem_mb": 3000,
        "options": ["walk_styles", "walk_variants", "keyframe_prominence", "keyframe_min_separation_s",
                    "fig3_max_clips", "fig3_phase_sd"],
    },
    "ma2010_fig6": {
        "input": "walks", "figure": "Fig. 6", "mem_mb": 4000,
        "options": [*_MODEL, "seed", "loo_max_clips", "loo_unit", "fig6_stride_reference"],
        "extra": MA2010_MODEL,
    },
    "ma2010_variogram": {
        "input": "walks", "figure": "Sec. 6 (variogram)", "mem_mb": 3000,
        "options": [*_MODEL, "variogram_scale", "seed"],
    },
    "ma2010_fig7b": {
        "input": "walks", "figure": "Fig. 7b", "mem_mb": 3000,
        "options": [*_MODEL, "reliability_grid", "reliability_margin"],
    },
    "ma2010_fig8": {
        "input": "walks", "figure": "Fig. 8a", "mem_mb": 3000,
        "options": [*_MODEL, "seed", "fig8_variants", "spread_ratio_bounds"],
    },
    # one core (95-125 % of one, measured): its rivals run on two torch/BLAS threads inside
    # (sec7_4.RIVAL_THREADS: the same numbers whatever cores the job gets)
    "ma2010_sec7_4": {
        "input": "walks", "figure": "Sec. 7.4", "mem_mb": 4000,
        "options": [*_MODEL, "seed", "comparison_examples", "comparison_seconds", "comparison_sequences",
                    "perlin_amplitude_rad", "perlin_frequency_hz", "gplvm_latent_dim", "gplvm_iterations",
                    "gplvm_frame_step", "dbn_max_parents", "contact_height_cm", "discontinuity_factor",
                    "comparison_xi", "comparison_landing", "animation_seconds"],
        "output": {
            "animation": in_report(
                "results/{dataset}/figures/ma2010_sec7_4.gif", "ma2010", "../report/ma2010_sec7_4.rst",
                figure="Sec. 7.4", kind="animation",
            ),
        },
        "params": {"animation": config_params("report", ["animation_fps", "animation_panel_px"])},
    },
    "ma2010_sec8": {
        "input": "walks", "figure": "Sec. 8", "mem_mb": 3000,
        "options": [*_MODEL, "seed", "timing_seconds", "timing_repeats"],
    },
}

for _ev, _spec in MA2010_EVALUATIONS.items():
    register_evaluation(_ev, paper="ma2010", extra=[p for p in _spec.get("output", {}).values() if p.endswith(".gif")]
                        + _spec.get("extra", []))
