"""Du 2022 ch. 5: stylistic motion primitives from a convolutional motion autoencoder,
a VAE per primitive and a CVAE per style with a Gram-matrix style loss.

Typical use (one primitive, clips resampled to the canonical 60 frames)::

    from motionvar.du2022.style import (FeatureScaler, FeatureSpace, StyleSettings, motions_features,
                                 sliding_windows, style_joints, train_autoencoder, train_cvae, train_vae)

    s = StyleSettings()                                        # the thesis' values (Sec. 5.4.1)
    layout = style_joints(skeleton, joint_map)                 # 21 joints (Sec. 5.2)
    windows = sliding_windows([motion_features(m, layout) for m in all_clips], 60, 30)
    scaler = FeatureScaler(layout.n_joints).fit(windows)
    ae, hist = train_autoencoder(scaler.transform(windows), s.autoencoder, s.seed)
    space = FeatureSpace(ae, scaler)                           # Eq. 5.1-5.2
    maps = space.encode(motions_features(neutral_clips, layout))
    vae, hist = train_vae(maps, s.vae, s.seed)                 # Eq. 5.6-5.8
    cvae, hist = train_cvae(maps, space.encode(example[None])[0], s.vae, s.cvae, s.seed,
                            init=vae)                          # Eq. 5.9-5.11
    samples = sample_features(cvae, maps.shape[1:], space, n=1000, seed=0)
    diversity(samples, layout.n_joints)                        # Eq. 5.13-5.15

Modules: :mod:`.settings` (config section ``du2022_style``), :mod:`.features` (Sec. 5.2 representation, windows, scaling),
:mod:`.networks` (Eq. 5.1-5.2, Fig. 5.3), :mod:`.losses` (Eq. 5.6-5.12),
:mod:`.training` (training runs; from a dataset to the saved models),
:mod:`.model` (feature space, save/load, sampling), :mod:`.data` (clips of a primitive,
style examples), :mod:`.diversity` (Eq. 5.13-5.15), :mod:`.published` (the thesis'
Tables 5.1-5.3), :mod:`.evaluations` (Table 5.1, Tables 5.2-5.3, Fig. 5.4-5.5) and
:mod:`.figures`.
"""

from ...core.lazy import lazy_exports
from .diversity import diversity, pose_sd, step_lengths, step_sd, velocity_sd

_EXPORTS = {
    ".features": [
        "FeatureLayout",
        "FeatureScaler",
        "features_to_positions",
        "heading_angles",
        "motion_features",
        "motions_features",
        "positions_to_features",
        "sliding_windows",
        "split_features",
        "style_joints",
    ],
    ".losses": [
        "content_loss",
        "gram",
        "gram_distance",
        "gram_distance_maps",
        "kl_loss",
        "latent_spread_penalty",
        "style_distance",
        "style_loss",
        "vae_loss",
    ],
    ".evaluations": [
        "diagonal_minima",
        "evaluate_fig5_4",
        "evaluate_table5_1",
        "evaluate_table5_2",
        "style_distance_matrix",
    ],
    ".model": ["FeatureSpace", "SavedVAE", "active_units", "load_vae", "sample_features", "sample_maps", "save_vae"],
    ".networks": ["ConvAutoencoder", "MotionVAE"],
    ".training": [
        "TrainConfig",
        "fit_feature_space",
        "fit_primitive_vae",
        "fit_style_cvae",
        "neutral_content",
        "train_autoencoder",
        "train_cvae",
        "train_vae",
    ],
    ".settings": ["AutoencoderSettings", "CvaeSettings", "StyleSettings", "VaeSettings"],
}
__getattr__, __dir__ = lazy_exports(__name__, _EXPORTS)

__all__ = [
    "AutoencoderSettings",
    "ConvAutoencoder",
    "CvaeSettings",
    "FeatureLayout",
    "active_units",
    "FeatureScaler",
    "FeatureSpace",
    "MotionVAE",
    "SavedVAE",
    "StyleSettings",
    "TrainConfig",
    "content_loss",
    "diagonal_minima",
    "diversity",
    "evaluate_fig5_4",
    "evaluate_table5_1",
    "evaluate_table5_2",
    "features_to_positions",
    "fit_feature_space",
    "fit_primitive_vae",
    "fit_style_cvae",
    "gram",
    "gram_distance",
    "gram_distance_maps",
    "heading_angles",
    "kl_loss",
    "latent_spread_penalty",
    "load_vae",
    "motion_features",
    "motions_features",
    "neutral_content",
    "pose_sd",
    "positions_to_features",
    "sample_features",
    "sample_maps",
    "save_vae",
    "sliding_windows",
    "split_features",
    "step_lengths",
    "step_sd",
    "style_distance",
    "style_distance_matrix",
    "style_joints",
    "style_loss",
    "train_autoencoder",
    "train_cvae",
    "train_vae",
    "VaeSettings",
    "vae_loss",
    "velocity_sd",
]
