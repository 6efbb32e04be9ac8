"""Image comparison against the analytic reference.

Two numbers judge a rendering ``I`` against the exact image ``I_ref``:

- the silhouette IoU: |hit(I) n hit(I_ref)| / |hit(I) u hit(I_ref)| (1 when both are empty);
- the fraction of compared pixels with |I - I_ref| <= 0.05 (I_max - I_min), I_max and
  I_min the extremes of the reference. Compared pixels are inside both silhouettes, away
  from them by at least one pixel (the 3x3 neighbourhood is inside both), and away from
  the discontinuities of the exact image: pixels whose 3x3 neighbourhood in the reference
  holds another surface id (CSG seams, face edges, cap rims, occluding contours).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .raycaster import ReferenceImage

__all__ = [
    "FLOAT32_ULPS",
    "fraction_within",
    "TOLERANCE",
    "Comparison",
    "silhouette_iou",
    "neighbourhood_all",
    "comparison_mask",
    "compare",
    "compare_images",
]

#: Relative tolerance on intensities, as a fraction of the reference's range.
TOLERANCE = 0.05


def silhouette_iou(image: NDArray[np.floating], reference: NDArray[np.floating]) -> float:
    """Intersection over union of the non-NaN pixels of two images (1.0 when both are empty)."""
    a = np.isfinite(np.asarray(image))
    b = np.isfinite(np.asarray(reference))
    if a.shape != b.shape:
        raise ValueError(f"image shape {a.shape} differs from the reference's {b.shape}")
    union = np.count_nonzero(a | b)
    return 1.0 if union == 0 else np.count_nonzero(a & b) / union


def neighbourhood_all(mask: NDArray[np.bool_]) -> NDArray[np.bool_]:
    """True where the whole 3x3 neighbourhood is True (outside the image counts as False)."""
    m = np.pad(np.asarray(mask, dtype=bool), 1, constant_values=False)
    h, w = mask.shape
    out = np.ones((h, w), dtype=bool)
    for di in range(3):
        for dj in range(3):
            out &= m[di : di + h, dj : dj + w]
    return out


def _same_neighbours(ids: NDArray[np.int64]) -> NDArray[np.bool_]:
    """True where every pixel of the 3x3 neighbourhood has the same id as the centre."""
    p = np.pad(ids, 1, mode="edge")
    h, w = ids.shape
    out = np.ones((h, w), dtype=bool)
    for di in range(3):
        for dj in range(3):
            out &= p[di : di + h, dj : dj + w] == ids
    return out


def comparison_mask(
    image: NDArray[np.floating], reference: ReferenceImage | NDArray[np.floating], *, seams: bool = True,
    surface_id: NDArray[np.int64] | None = None,
) -> NDArray[np.bool_]:
    """Pixels compared: inside both silhouettes minus a 1-pixel band, minus seams.

    Parameters
    ----------
    image : ndarray (H, W)
        The rendering under test (NaN background).
    reference : ReferenceImage or ndarray (H, W)
        The exact image, or another float image (then seams come from ``surface_id``).
    seams : bool, default True
        Also leave out pixels next to a change of the reference's surface id.
    surface_id : ndarray (H, W), optional
        Surface ids when ``reference`` is a plain image.
    """
    if isinstance(reference, ReferenceImage):
        ref_mask, ids = reference.mask, reference.surface_id
    else:
        ref_mask, ids = np.isfinite(reference), surface_id
    keep = neighbourhood_all(np.isfinite(image) & ref_mask)
    if seams and ids is not None:
        keep &= _same_neighbours(ids)
    return keep


@dataclass(frozen=True)
class Comparison:
    """Accuracy of one rendering against the reference.

    Attributes
    ----------
    iou : float
        Silhouette intersection over union.
    fraction : float
        Share of compared pixels within ``tol`` (1.0 when none is compared).
    mean_error, max_error : float
        Mean and maximum absolute error over the compared pixels.
    tol : float
        Absolute tolerance used, ``TOLERANCE * (I_max - I_min)``.
    compared, hit_ref, hit_image : int
        Number of compared pixels and of object pixels in each image.
    """

    iou: float
    fraction: float
    mean_error: float
    max_error: float
    tol: float
    compared: int
    hit_ref: int
    hit_image: int

    def summary(self) -> str:
        """One line for reports and assertion messages."""
        return (
            f"IoU {self.iou:.4f}, within tol {self.fraction:.4f} ({self.compared} px compared, "
            f"tol {self.tol:.4f}), mean |err| {self.mean_error:.5f}, max |err| {self.max_error:.4f}, "
            f"object px ref/img {self.hit_ref}/{self.hit_image}"
        )


def compare(image: NDArray[np.floating], reference: ReferenceImage, *, seams: bool = True) -> Comparison:
    """Compare a rendering with the reference; see the module docstring.

    If the reference has a single intensity (range 0), the tolerance is
    ``TOLERANCE * max(|I_max|, 1e-12)``.
    """
    return compare_images(image, reference.image, surface_id=reference.surface_id if seams else None)


def compare_images(
    image: NDArray[np.floating], expected: NDArray[np.floating], *, surface_id: NDArray[np.int64] | None = None
) -> Comparison:
    """:func:`compare` of two float images; seams are left out only where ``surface_id`` is given."""
    img = np.asarray(image, dtype=np.float64)
    ref = np.asarray(expected, dtype=np.float64)
    if img.shape != ref.shape:
        raise ValueError(f"image shape {img.shape} differs from the reference's {ref.shape}")
    iou = silhouette_iou(img, ref)
    ref_mask = np.isfinite(ref)
    if ref_mask.any():
        lo, hi = float(np.nanmin(ref)), float(np.nanmax(ref))
        span = hi - lo if hi > lo else max(abs(hi), 1e-12)
    else:
        span = 0.0
    tol = TOLERANCE * span
    keep = comparison_mask(img, ref, surface_id=surface_id)
    err = np.abs(img[keep] - ref[keep])
    n = int(err.size)
    return Comparison(
        iou=float(iou),
        fraction=float(np.count_nonzero(err <= tol) / n) if n else 1.0,
        mean_error=float(err.mean()) if n else 0.0,
        max_error=float(err.max()) if n else 0.0,
        tol=tol,
        compared=n,
        hit_ref=int(np.count_nonzero(ref_mask)),
        hit_image=int(np.count_nonzero(np.isfinite(img))),
    )


#: The renderer's images are float32 (the conventions): intensities are resolved to about this
#: many of its steps.
FLOAT32_ULPS = 4


def fraction_within(image: NDArray[np.floating], reference: ReferenceImage, result: Comparison) -> float:
    """``result.fraction``, except where the exact image varies by less than float32 resolves.

    The bar's tolerance is 5 % of the reference's range; when that range is below a few float32
    steps of its largest value (one face whose Phong term spans 1e-8, or a scene at scale 1e-3
    whose field barely changes), no float32 image can meet it, and the pixels are judged at
    :data:`FLOAT32_ULPS` float32 steps instead.
    """
    if not result.hit_ref:
        return result.fraction
    floor = FLOAT32_ULPS * float(np.finfo(np.float32).eps) * float(np.nanmax(np.abs(reference.image)))
    if result.tol >= floor:
        return result.fraction
    keep = comparison_mask(image, reference)
    if not keep.any():
        return 1.0
    return float(np.mean(np.abs(np.asarray(image, dtype=np.float64)[keep] - reference.image[keep]) <= floor))
