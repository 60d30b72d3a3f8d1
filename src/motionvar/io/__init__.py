"""Input and output: BVH files and packed datasets."""

from .bvh import BVHError, read_bvh, write_bvh
from .bvh_dataset import export_clip_bvh, import_bvh_folder
from .dataset import DatasetError, MotionDataset, load_dataset, save_dataset
from .joint_map_file import JointMapError, load_joint_map

__all__ = [
    "BVHError",
    "DatasetError",
    "JointMapError",
    "MotionDataset",
    "export_clip_bvh",
    "import_bvh_folder",
    "load_dataset",
    "load_joint_map",
    "read_bvh",
    "save_dataset",
    "write_bvh",
]
