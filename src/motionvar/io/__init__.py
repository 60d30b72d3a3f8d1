"""Input and output: BVH files and packed datasets."""

from .dataset import DatasetError, MotionDataset, load_dataset, save_dataset

__all__ = ["DatasetError", "MotionDataset", "load_dataset", "save_dataset"]
