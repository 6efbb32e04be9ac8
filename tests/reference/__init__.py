"""An analytic reference for the isoluminance renderer, independent of the library.

The ray caster reads only the parameters of primitives, CSG trees, lights,
materials and the camera; every ray, interval, normal and intensity is
computed here from the conventions, so that it can judge the library's
rendering paths pixel by pixel.
"""

from .metrics import Comparison, compare, compare_images, comparison_mask, fraction_within, silhouette_iou
from .raycaster import ReferenceImage, camera_rays, primitive_intervals, raycast, raycast_scene

__all__ = [
    "Comparison",
    "ReferenceImage",
    "camera_rays",
    "compare",
    "compare_images",
    "comparison_mask",
    "fraction_within",
    "primitive_intervals",
    "raycast",
    "raycast_scene",
    "silhouette_iou",
]
