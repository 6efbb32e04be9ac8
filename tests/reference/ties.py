"""Silhouette ties: pixel centres that lie on an exact silhouette to within a fraction of a pixel.

A renderer whose silhouettes are the chords of a band mesh (an inscribed
polygon whose sagitta is a few thousandths of a pixel) and the exact image
may disagree at such a pixel centre without either being wrong at the
resolution a pixel can show. A centre whose exact hit or miss flips when the
camera moves by ``tie_pixels`` of a pixel (right, left, up or down) is a tie.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace
from typing import Any

import numpy as np

from .raycaster import ReferenceImage, raycast_scene

__all__ = ["silhouette_ties"]


def silhouette_ties(
    scene: Any, *, tie_pixels: float = 0.01, reference: Callable[[Any], ReferenceImage] = raycast_scene
) -> np.ndarray:
    """Boolean ``(H, W)`` mask of the pixels whose exact coverage flips under a camera move of
    ``tie_pixels`` pixel along the camera's right or up axis (four moves)."""
    cam = scene.camera
    eye, target = np.asarray(cam.eye, dtype=float), np.asarray(cam.target, dtype=float)
    f = (target - eye) / np.linalg.norm(target - eye)
    r = np.cross(f, np.asarray(cam.up, dtype=float))
    r /= np.linalg.norm(r)
    u = np.cross(r, f)
    half = cam.height_m / 2 if cam.orthographic else np.linalg.norm(target - eye) * math.tan(math.radians(cam.fov) / 2)
    step = tie_pixels * 2 * half / cam.height
    base = np.isfinite(reference(scene).image)
    ties = np.zeros_like(base)
    for move in (r, -r, u, -u):
        moved = replace(cam, eye=tuple(eye + step * move), target=tuple(target + step * move))
        ties |= np.isfinite(reference(replace(scene, camera=moved)).image) != base
    return ties
