"""The shared band math below the kinds: what every kind's band surface is built from.

- :mod:`~isocsg.bands.lights`: what the band math reads of a light and a material (protocols);
- :mod:`~isocsg.bands.families`: the shading fields, their levels and band values;
- :mod:`~isocsg.bands.surface`: :class:`~isocsg.bands.surface.Surface` (the base mesh a kind's
  bands are cut from), its orientation, and the mesh spacings that follow every field.

Each kind's own construction lives next to the kind (``isocsg/kinds/<kind>_bands.py``); the
builder that cuts a surface into bands and laminae is :mod:`isocsg.laminae`, above the kinds.
This package imports no kind and no light class.
"""

__all__: list[str] = []
