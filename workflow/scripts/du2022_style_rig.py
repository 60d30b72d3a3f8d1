"""Rule du2022_style_rig (Du 2022 ch. 5): what decoding the style models into joint
rotations on the dataset's rig needs and the models do not hold: the rig's mean skeleton,
its feature layout (Sec. 5.2) and each primitive's real-time frame rate
(motionvar.du2022.style.generate), for the `motionvar du2022 style` command."""


def main(snakemake) -> None:
    import logging

    from _rule import joint_map
    from _style import load_inputs, load_settings

    from motionvar.du2022.style.generate import fit_rig, save_rig

    dataset, _, _ = load_inputs(snakemake)
    rig = fit_rig(dataset, joint_map(snakemake), load_settings(snakemake).canonical_frames)
    save_rig(snakemake.output.model, rig)
    logging.info(
        "%d joints, %d feature joints; fps per primitive %s", rig.skeleton.n_joints, rig.layout.n_joints, rig.fps
    )


if "snakemake" in globals():
    from _rule import run

    run(snakemake, main)  # noqa: F821
