"""Point and directional lights, materials, and the exact shading formula."""

from .lights import DirectionalLight, Light, Material, PointLight
from .shading import shade

__all__ = ["PointLight", "DirectionalLight", "Light", "Material", "shade"]
