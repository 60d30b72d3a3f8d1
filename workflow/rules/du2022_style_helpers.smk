# Helpers of du2022_style.smk (Du 2022 ch. 5), kept apart from its rules (snakemake --lint).

from motionvar.core.joint_map import OPTIONAL_JOINTS  # the features' hands and toes (du2022.requirements.STYLE_JOINTS)

STYLE_CFG = config["du2022_style"]
STYLE_MODELS = "results/{dataset}/models/du2022_style"
STYLE_PRIMITIVE_PATTERN = "[A-Za-z]+(?:_[A-Za-z]+)?"
# A saved model is <base>.pt (torch state dict) + <base>.json (settings); its training
# history is <base>_history.csv.
STYLE_SUFFIX = {"model": ".pt", "settings": ".json", "history": "_history.csv"}
# what decoding the models onto the rig needs (rule du2022_style_rig), for `motionvar du2022 style`;
# it needs only the prep stage, so every dataset whose rig has hands and toes (the features' joints)
# gets it (DATASET_MODELS)
STYLE_RIG = [f"{STYLE_MODELS}/rig.npz", f"{STYLE_MODELS}/rig.json"]
DATASET_MODELS.extend((p, OPTIONAL_JOINTS) for p in STYLE_RIG)
# rule du2022_style_training_curves' figure (joins the default target with Tables 5.2-5.3)
STYLE_TRAINING_FIGURE = "results/{dataset}/figures/du2022_style_training.png"


def style_vaes(primitives, kind="model"):
    """The files of the neutral VAEs of ``primitives``: kind model, settings or history."""
    return [f"{STYLE_MODELS}/vae/{p}{STYLE_SUFFIX[kind]}" for p in primitives]


def style_cvaes(primitives, kind="model"):
    """The files of the CVAEs of ``primitives`` and every configured style."""
    return [f"{STYLE_MODELS}/cvae/{p}/{s}{STYLE_SUFFIX[kind]}" for p in primitives for s in STYLE_CFG["styles"]]


def style_evaluation_inputs(vae_primitives, cvae_primitives):
    """The inputs of an evaluation: the prepared clips, the autoencoder, the neutral VAEs of
    ``vae_primitives`` and the CVAEs (every configured style) of ``cvae_primitives``."""
    return dict(
        clips=f"{PREP}/clips.npz",
        metadata=f"{PREP}/metadata.csv",
        autoencoder=f"{STYLE_MODELS}/autoencoder.pt",
        autoencoder_settings=f"{STYLE_MODELS}/autoencoder.json",
        vaes=style_vaes(vae_primitives),
        vae_settings=style_vaes(vae_primitives, "settings"),
        cvaes=style_cvaes(cvae_primitives),
        cvae_settings=style_cvaes(cvae_primitives, "settings"),
        cvae_histories=style_cvaes(cvae_primitives, "history"),
        joint_map=joint_map_input,
    )
